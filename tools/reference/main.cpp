// SPDX-License-Identifier: MIT
// shadowgraph-reference: how far each shadow algorithm is from ray-traced visibility, light by
// light, on any scene the sandbox opens (run_reference.h says how), or with --whole-frame the
// frame as the engine draws it, every light on (whole_frame.h). Every frame setting applies
// (scene, camera, size, device: systems/frame/frame_settings.h); animation is off light by light,
// and as the settings say for the whole frame.
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "rendergraph/device/context.h"
#include "systems/frame/command_line.h"
#include "systems/frame/frame_settings.h"
#include "systems/frame/interrupt.h"
#include "tools/reference/report.h"
#include "tools/reference/run_reference.h"
#include "tools/reference/whole_frame_report.h"

int main(int argc, char** argv) {
  // Progress lines reach a log file as they are written, not when a buffer fills: a run cut off
  // by a time limit still says how far it got.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  sg::FrameSettings frame;
  frame.width = 640;
  frame.height = 360;
  sg::reference::ReferenceSettings settings;
  std::vector<std::string> algorithm_names;
  std::string json_path = "reference.json";
  settings.image_folder = "reference";
  settings.cost_frames = 10;

  bool whole_frame = false;
  sg::reference::WholeFrameSettings frame_mode;

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
  app.add_option("--light", settings.light_filter,
                 "Only lights whose name contains this text (--whole-frame: the others are switched off)");
  app.add_option("--no-shadow-from", settings.no_shadow_from,
                 "Meshes (or glTF nodes) whose name contains this cast no shadow, in the render and the "
                 "reference: a marker mesh around a light (repeatable)");
  app.add_option("--max-lights", settings.max_lights, "At most this many lights, in scene order (0: all)")
      ->capture_default_str();
  app.add_option("--images", settings.image_folder, "Folder for the PNGs per light (empty: none)")
      ->capture_default_str();
  sg::check_writable_output(
      *app.add_option("--json", json_path, "Where the results go as JSON (empty: nowhere)")
           ->capture_default_str());
  app.add_option("--cost-frames", settings.cost_frames,
                 "Frames per algorithm for the GPU cost on the whole scene (0: not measured)")
      ->check(CLI::Range(0u, 100000u))
      ->capture_default_str();
  app.add_flag("--whole-frame", whole_frame,
               "Measure the frame as the engine draws it, every light on, at its tiers and caching, instead "
               "of each light alone; each light weighted by what its shadow can change at the pixel");
  app.add_option(
         "--frames", frame_mode.frames,
         "--whole-frame: frames rendered (animation advancing 1/60 s each), the last measured, so that "
         "maps waiting their turn count as error")
      ->check(CLI::Range(1u, 100000u))
      ->capture_default_str();
  app.add_option(
         "--pairs-per-pixel", frame_mode.pairs_per_pixel,
         "--whole-frame: room for this many (pixel, light) pairs a pixel; a frame with more is measured "
         "on a random sample of them, which the output says")
      ->check(CLI::Range(1u, 4096u))
      ->capture_default_str();
  app.add_option("--worst-lights", frame_mode.worst_lights, "--whole-frame: light rows reported")
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
  const auto print = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  try {
    sg::vk::VulkanContext context(sg::context_options(frame));
    nlohmann::json json;
    if (whole_frame) {
      // A pair's soft reference costs a ray each sample: fewer than light by light by default.
      frame_mode.soft_samples = app.count("--soft-samples") > 0 ? settings.soft_samples : 16u;
      frame_mode.edge_band = settings.edge_band;
      frame_mode.light_filter = settings.light_filter;
      const sg::reference::WholeFrameReport report =
          sg::reference::run_whole_frame(context, frame, frame_mode, print);
      sg::reference::print_whole_frame(stdout, report);
      json = sg::reference::to_json(report);
    } else {
      // Light by light, Ctrl-C ends the run after the light in hand and the lights compared so far
      // are still reported (the whole frame is one measurement: Ctrl-C ends it at once).
      sg::catch_interrupts();
      const sg::reference::ReferenceReport report =
          sg::reference::run_reference(context, frame, settings, print);
      if (report.interrupted) {
        print("interrupted after " + std::to_string(report.lights.size()) +
              " lights: reporting those, without the costs (a second Ctrl-C ends at once)");
      }
      sg::reference::print_tables(stdout, report);
      json = sg::reference::to_json(report);
    }
    if (!json_path.empty()) {
      sg::reference::write_json(json_path, json);
      std::printf("\nwrote %s\n", json_path.c_str());
    }
    if (context.validation_enabled() && context.validation_errors() > 0) return 3;
    return sg::interrupted() ? 130 : 0;  // 128 + SIGINT, as shells report a run Ctrl-C ended
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowgraph-reference: error: %s\n", e.what());
    return 1;
  }
}
