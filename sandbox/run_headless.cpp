#include <cstdio>

#include "rendergraph/device/context.h"
#include "rendergraph/device/frame_ring.h"
#include "sandbox/gpu_time_log.h"
#include "sandbox/headless_frames.h"
#include "sandbox/run.h"
#include "sandbox/sandbox_frame.h"
#include "sandbox/scene_setup.h"

namespace sg::sandbox {

int run_headless(const Options& options) {
  SandboxScene scene = load_sandbox_scene(options, float(options.width) / float(options.height));
  vk::VulkanContext context(context_options(options));
  std::printf("shadowgraph: headless on %s, %ux%u, scene %s, camera from %s\n", context.device_name().c_str(),
              options.width, options.height, scene.scene.name.c_str(), scene.camera_source.c_str());

  vk::FrameRing frames(context);
  SandboxFrame frame(context, scene, options, frames.frames_in_flight());
  frame.resize({options.width, options.height});
  GpuTimeLog gpu_times;
  const RunRecord record = render_headless_frames(frame, frames, options.frames.value_or(3), gpu_times, true);
  return finish_run(options, context, scene, frame, record);
}

}  // namespace sg::sandbox
