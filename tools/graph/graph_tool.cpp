// SPDX-License-Identifier: MIT
// shadowgraph-graph: renders a few headless frames of a scene and writes the frame's
// compiled render graph as Graphviz DOT and as JSON (with the last timed frame's per-pass GPU
// milliseconds), plus a PNG of the DOT when Graphviz's `dot` is installed.
//
//   shadowgraph-graph --scene default --out frame     -> frame.dot, frame.json, frame.png
//
// Every frame setting (scene, size, lighting, device...; systems/frame/frame_settings.h) applies.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "rendergraph/core/dump.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/frame_ring.h"
#include "systems/frame/command_line.h"
#include "systems/frame/frame.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/headless_frames.h"
#include "systems/frame/scene_view.h"

namespace {

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
  std::printf("shadowgraph-graph: wrote %s\n", path.c_str());
}

bool dot_available() { return std::system("command -v dot >/dev/null 2>&1") == 0; }

}  // namespace

int main(int argc, char** argv) {
  sg::FrameSettings settings;
  settings.width = 640;
  settings.height = 360;
  std::string out = "frame";
  uint32_t frame_count = 0;
  CLI::App app{"Writes the frame's compiled render graph as DOT, JSON and PNG."};
  sg::add_settings(app, sg::frame_settings_table(), settings);
  app.add_option("--frames", frame_count, "Frames to render before the dump (0: frames in flight + 1)")
      ->check(CLI::Range(0u, 100000u))
      ->capture_default_str();
  app.add_option("--out", out, "Output path without extension")->capture_default_str();
  if (const std::optional<int> exit_code = sg::parse_command_line(app, argc, argv)) {
    return *exit_code;
  }

  try {
    sg::SceneView view = sg::load_scene_view(settings, float(settings.width) / float(settings.height));
    sg::vk::VulkanContext context(sg::context_options(settings));
    sg::vk::FrameRing frames(context);
    sg::Frame frame(context, view, settings, frames.frames_in_flight());
    frame.resize({settings.width, settings.height});
    // A few frames, so that the dumped plan is one the cache served, as in a running sandbox.
    sg::GpuTimeLog gpu_times;
    sg::render_headless_frames(frame, frames, frame_count > 0 ? frame_count : frames.frames_in_flight() + 1,
                               gpu_times);

    // The last frame's graph and plan; its timings when they are that frame's.
    const auto& timings = frame.executor().latest_timings();
    std::vector<double> pass_ms;
    if (timings && timings->plan == frame.plan()) pass_ms = timings->pass_ms;
    write_file(out + ".dot", sg::rg::to_dot(frame.graph(), *frame.plan()));
    write_file(out + ".json", sg::rg::to_json(*frame.plan(), pass_ms));
    if (dot_available()) {
      const std::string command = "dot -Tpng -o '" + out + ".png' '" + out + ".dot'";
      if (std::system(command.c_str()) != 0) throw std::runtime_error("dot failed: " + command);
      std::printf("shadowgraph-graph: wrote %s.png\n", out.c_str());
    } else {
      std::printf("shadowgraph-graph: Graphviz's dot is not installed: no PNG (apt-get install graphviz)\n");
    }
    if (context.validation_enabled() && context.validation_errors() > 0) return 3;
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowgraph-graph: error: %s\n", e.what());
    return 1;
  }
}
