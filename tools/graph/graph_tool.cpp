// shadowgraph-graph: renders a few headless frames of a sandbox scene and writes the frame's
// compiled render graph as Graphviz DOT and as JSON (with the last timed frame's per-pass GPU
// milliseconds), plus a PNG of the DOT when Graphviz's `dot` is installed.
//
//   shadowgraph-graph --scene default --out frame     -> frame.dot, frame.json, frame.png
//
// Every sandbox option (scene, size, overlay, device...) applies.
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
#include "sandbox/gpu_time_log.h"
#include "sandbox/headless_frames.h"
#include "sandbox/options.h"
#include "sandbox/sandbox_frame.h"
#include "sandbox/scene_setup.h"

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
  sg::sandbox::Options options;
  options.width = 640;
  options.height = 360;
  std::string out = "frame";
  CLI::App app{"Writes the sandbox frame's compiled render graph as DOT, JSON and PNG."};
  sg::sandbox::add_options(app, options);
  app.add_option("--out", out, "Output path without extension")->capture_default_str();
  if (const std::optional<int> exit_code = sg::sandbox::parse_command_line(app, argc, argv, options)) {
    return *exit_code;
  }

  try {
    sg::sandbox::SandboxScene scene =
        sg::sandbox::load_sandbox_scene(options, float(options.width) / float(options.height));
    sg::vk::VulkanContext context(sg::sandbox::context_options(options));
    sg::vk::FrameRing frames(context);
    sg::sandbox::SandboxFrame frame(context, scene, options, frames.frames_in_flight());
    frame.resize({options.width, options.height});
    // A few frames, so that the dumped plan is one the cache served, as in a running sandbox.
    sg::sandbox::GpuTimeLog gpu_times;
    sg::sandbox::render_headless_frames(frame, frames, options.frames.value_or(frames.frames_in_flight() + 1),
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
