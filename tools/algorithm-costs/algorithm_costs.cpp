// shadowgraph-algorithm-costs: the GPU cost of each shadow algorithm, per shadowed light, on a
// sandbox scene (issue 6's comparison of the five algorithms).
//
// For each algorithm it renders the scene with every light forced to it (--algorithm), and once
// with shadows off; the lighting pass's extra time over "off", divided by the lights that cast a
// shadow, is the algorithm's cost per light at that resolution. Shadow-map passes do not depend
// on the algorithm and are reported once. Prints a Markdown table; every sandbox option applies.
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "rendergraph/device/context.h"
#include "rendergraph/device/frame_ring.h"
#include "sandbox/gpu_time_log.h"
#include "sandbox/headless_frames.h"
#include "sandbox/options.h"
#include "sandbox/sandbox_frame.h"
#include "sandbox/scene_setup.h"

namespace {

using sg::sandbox::Options;
using sg::sandbox::PassTime;

struct Measurement {
  double forward_ms = 0.0;  // median of the lighting pass
  double shadow_ms = 0.0;   // median per frame of all shadow-map passes
  double frame_ms = 0.0;
  uint32_t shadowed_lights = 0;
};

Measurement measure(sg::vk::VulkanContext& context, const Options& options, uint32_t frames) {
  sg::sandbox::SandboxScene scene =
      sg::sandbox::load_sandbox_scene(options, float(options.width) / float(options.height));
  sg::vk::FrameRing ring(context);
  sg::sandbox::SandboxFrame frame(context, scene, options, ring.frames_in_flight());
  frame.resize({options.width, options.height});
  sg::sandbox::GpuTimeLog log;
  sg::sandbox::render_headless_frames(frame, ring, frames, log);
  Measurement m;
  for (const PassTime& pass : log.pass_summaries()) {
    if (pass.name == "forward") m.forward_ms = pass.gpu_ms.median;
    if (pass.name.rfind("shadow", 0) == 0) m.shadow_ms += pass.gpu_ms.median;
  }
  if (const auto frame_ms = sg::sandbox::summarize(log.frame_ms())) m.frame_ms = frame_ms->median;
  const sg::shadows::FrameLights& lights = frame.renderer().lights();
  m.shadowed_lights = static_cast<uint32_t>(lights.maps.size() + lights.cubes.size());
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  options.width = 640;
  options.height = 360;
  uint32_t frames = 20;
  CLI::App app{"Measures each shadow algorithm's GPU cost per light on a sandbox scene."};
  sg::sandbox::add_options(app, options);
  app.add_option("--timed-frames", frames, "Frames per algorithm (the median is reported)")
      ->check(CLI::Range(3u, 100000u))
      ->capture_default_str();
  if (const std::optional<int> exit_code = sg::sandbox::parse_command_line(app, argc, argv, options)) {
    return *exit_code;
  }
  try {
    sg::vk::VulkanContext context(sg::sandbox::context_options(options));
    std::printf("device: %s, %ux%u, scene %s, %u frames per row\n\n", context.device_name().c_str(),
                options.width, options.height, options.scene.c_str(), frames);
    Options off = options;
    off.shadows = false;
    const Measurement base = measure(context, off, frames);
    std::printf(
        "| algorithm | lighting pass (ms) | over shadows off (ms) | per shadowed light (ms) | shadow maps "
        "(ms) | GPU frame (ms) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|\n");
    std::printf("| off | %.3f | - | - | - | %.3f |\n", base.forward_ms, base.frame_ms);
    for (const sg::scene::ShadowAlgorithm algorithm : sg::scene::all_shadow_algorithms) {
      Options run = options;
      run.algorithm = algorithm;
      const Measurement m = measure(context, run, frames);
      const double extra = m.forward_ms - base.forward_ms;
      std::printf("| %s | %.3f | %.3f | %.4f | %.3f | %.3f |\n",
                  std::string(sg::scene::to_string(algorithm)).c_str(), m.forward_ms, extra,
                  m.shadowed_lights ? extra / m.shadowed_lights : 0.0, m.shadow_ms, m.frame_ms);
      std::fflush(stdout);
    }
    if (context.validation_enabled() && context.validation_errors() > 0) return 3;
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowgraph-algorithm-costs: error: %s\n", e.what());
    return 1;
  }
}
