// SPDX-License-Identifier: MIT
// shadowgraph-algorithm-costs: the GPU cost of each shadow algorithm, per shadowed light, on a
// scene (the comparison of the five algorithms).
//
// For each algorithm it renders the scene with every light forced to it (--algorithm), and once
// with shadows off; the lighting passes' extra time over "off" (every pass but the shadow maps),
// divided by the lights that cast a shadow, is the algorithm's cost per light at that resolution. Shadow-map
// passes do not depend on the algorithm and are reported once. Prints a Markdown table; every frame setting
// (systems/frame/frame_settings.h) applies.
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "rendergraph/device/context.h"
#include "systems/frame/command_line.h"
#include "systems/frame/frame_cost.h"
#include "systems/frame/frame_settings.h"

using sg::FrameCost;
using sg::FrameSettings;

int main(int argc, char** argv) {
  FrameSettings settings;
  settings.width = 640;
  settings.height = 360;
  uint32_t frames = 20;
  CLI::App app{"Measures each shadow algorithm's GPU cost per light on a scene."};
  sg::add_settings(app, sg::frame_settings_table(), settings);
  app.add_option("--timed-frames", frames, "Frames per algorithm (the median is reported)")
      ->check(CLI::Range(3u, 100000u))
      ->capture_default_str();
  if (const std::optional<int> exit_code = sg::parse_command_line(app, argc, argv)) {
    return *exit_code;
  }
  try {
    sg::vk::VulkanContext context(sg::context_options(settings));
    std::printf("device: %s, %ux%u, scene %s, %u frames per row\n\n", context.device_name().c_str(),
                settings.width, settings.height, settings.scene.c_str(), frames);
    FrameSettings off = settings;
    off.renderer.lights.shadows = false;
    const FrameCost base = sg::measure_frame_cost(context, off, frames);
    std::printf(
        "| algorithm | lighting passes (ms) | over shadows off (ms) | per shadowed light (ms) | shadow maps "
        "(ms) | GPU frame (ms) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|\n");
    std::printf("| off | %.3f | - | - | - | %.3f |\n", base.lighting_ms, base.frame_ms);
    for (const sg::scene::ShadowAlgorithm algorithm : sg::scene::all_shadow_algorithms) {
      FrameSettings run = settings;
      run.algorithm = algorithm;
      const FrameCost m = sg::measure_frame_cost(context, run, frames);
      const double extra = m.lighting_ms - base.lighting_ms;
      std::printf("| %s | %.3f | %.3f | %.4f | %.3f | %.3f |\n",
                  std::string(sg::to_string(algorithm)).c_str(), m.lighting_ms, extra,
                  m.shadowed_lights ? extra / m.shadowed_lights : 0.0, m.shadow_maps_ms, m.frame_ms);
      std::fflush(stdout);
    }
    if (context.validation_enabled() && context.validation_errors() > 0) return 3;
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowgraph-algorithm-costs: error: %s\n", e.what());
    return 1;
  }
}
