#include <chrono>
#include <cstdio>

#include "rendergraph/vulkan/context.h"
#include "rendergraph/vulkan/frame_ring.h"
#include "sandbox/gpu_time_log.h"
#include "sandbox/run.h"
#include "sandbox/sandbox_frame.h"
#include "sandbox/scene_setup.h"

namespace sg::sandbox {

int run_headless(const Options& options) {
  SandboxScene scene = load_sandbox_scene(options, float(options.width) / float(options.height));
  vk::VulkanContext context(context_options(options));
  std::printf("shadowgraph: headless on %s, %ux%u, scene %s, camera from %s\n",
              context.device_name().c_str(), options.width, options.height,
              scene.scene.name.c_str(), scene.camera_source.c_str());

  vk::FrameRing frames(context);
  SandboxFrame frame(context, scene, options, frames.frames_in_flight());
  frame.resize({options.width, options.height});

  // Animation advances a fixed 1/60 s per frame, so headless runs are reproducible.
  constexpr double frame_seconds = 1.0 / 60.0;
  const uint32_t frame_count = options.frames.value_or(3);
  GpuTimeLog gpu_times;
  RunRecord record{{}, &gpu_times};
  for (uint32_t i = 0; i < frame_count; ++i) {
    vk::FrameSlot& slot = frames.begin_frame();
    const auto start = std::chrono::steady_clock::now();  // after the wait for the GPU
    frame.record(slot, i * frame_seconds);
    frames.submit();
    gpu_times.add(frame.executor().latest_timings());
    record.cpu_frame_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    if (frame_count >= 100 && (i + 1) % (frame_count / 10) == 0) {
      std::printf("shadowgraph: %u/%u frames\n", i + 1, frame_count);
    }
  }
  frames.wait_idle();
  // The last frames' timings become readable once the GPU is idle, oldest first.
  const uint32_t in_flight = frames.frames_in_flight();
  for (uint32_t i = frame_count > in_flight ? frame_count - in_flight : 0; i < frame_count; ++i) {
    frame.executor().collect_timings(i % in_flight);
    gpu_times.add(frame.executor().latest_timings());
  }
  return finish_run(options, context, scene, frame, record);
}

}  // namespace sg::sandbox
