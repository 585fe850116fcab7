// shadowgraph-reference: how far each shadow algorithm is from ray-traced visibility, light by
// light, on any scene the sandbox opens (run_reference.h says how). Every frame setting applies
// (scene, camera, size, device: systems/frame/frame_settings.h); animation is off.
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "rendergraph/device/context.h"
#include "systems/frame/command_line.h"
#include "systems/frame/frame_settings.h"
#include "tools/reference/report.h"
#include "tools/reference/run_reference.h"

int main(int argc, char** argv) {
  sg::FrameSettings frame;
  frame.width = 640;
  frame.height = 360;
  sg::reference::ReferenceSettings settings;
  std::vector<std::string> algorithm_names;
  std::string json_path = "reference.json";
  settings.image_folder = "reference";
  settings.cost_frames = 10;

  CLI::App app{"Compares each shadow algorithm with a ray-traced (Embree) reference on a scene."};
  sg::add_settings(app, sg::frame_settings_table(), frame);
  app.add_option("--algorithms", algorithm_names, "Algorithms to compare (default: all five)")
      ->delimiter(',')
      ->check(CLI::IsMember({"hard", "pcf", "noise", "pcss", "pcss_noise"}));
  app.add_option("--resolutions", settings.resolutions,
                 "Shadow map sizes to request, e.g. 32,64,...,2048 (default: each light's own)")
      ->delimiter(',')
      ->check(CLI::Range(16u, 4096u));
  app.add_option("--constant-bias", settings.constant_bias, "Every light's constant bias (default: its own)")
      ->check(CLI::Range(0.0f, 1.0f));
  app.add_option("--slope-bias", settings.slope_bias, "Every light's slope bias (default: its own)")
      ->check(CLI::Range(0.0f, 1.0f));
  app.add_option("--soft-samples", settings.soft_samples, "Rays per pixel of the soft (PCSS) reference")
      ->check(CLI::Range(1u, 4096u))
      ->capture_default_str();
  app.add_option("--edge-band", settings.edge_band,
                 "Pixels each side of the reference edge left out of "
                 "the misclassified count")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  app.add_option("--light", settings.light_filter, "Only lights whose name contains this text");
  app.add_option("--no-shadow-from", settings.no_shadow_from,
                 "Meshes (or glTF nodes) whose name contains this cast no shadow, in the render and the "
                 "reference: a marker mesh around a light (repeatable)");
  app.add_option("--max-lights", settings.max_lights, "At most this many lights, in scene order (0: all)")
      ->capture_default_str();
  app.add_option("--images", settings.image_folder, "Folder for the PNGs per light (empty: none)")
      ->capture_default_str();
  app.add_option("--json", json_path, "Where the results go as JSON (empty: nowhere)")->capture_default_str();
  app.add_option("--cost-frames", settings.cost_frames,
                 "Frames per algorithm for the GPU cost on the whole scene (0: not measured)")
      ->check(CLI::Range(0u, 100000u))
      ->capture_default_str();
  if (const std::optional<int> exit_code = sg::parse_command_line(app, argc, argv)) {
    return *exit_code;
  }
  if (!algorithm_names.empty()) {
    settings.algorithms.clear();
    for (const std::string& name : algorithm_names) {
      settings.algorithms.push_back(*sg::parse_enum<sg::scene::ShadowAlgorithm>(name));
    }
  }
  if (settings.cost_frames > 0 && settings.cost_frames < 3) {
    std::fprintf(stderr, "--cost-frames: at least 3 frames for a median (or 0 to skip the cost)\n");
    return 2;
  }
  try {
    sg::vk::VulkanContext context(sg::context_options(frame));
    const sg::reference::ReferenceReport report =
        sg::reference::run_reference(context, frame, settings, [](const std::string& line) {
          std::printf("%s\n", line.c_str());
          std::fflush(stdout);
        });
    sg::reference::print_tables(stdout, report);
    if (!json_path.empty()) {
      sg::reference::write_json(json_path, report);
      std::printf("\nwrote %s\n", json_path.c_str());
    }
    if (context.validation_enabled() && context.validation_errors() > 0) return 3;
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowgraph-reference: error: %s\n", e.what());
    return 1;
  }
}
