#include <chrono>
#include <cstdio>

#include "rendergraph/vulkan/context.h"
#include "rendergraph/vulkan/frame_ring.h"
#include "sandbox/run.h"
#include "systems/scene_renderer.h"

namespace sg::sandbox {

int run_headless(const Options& options) {
  vk::VulkanContext context(context_options(options));
  std::printf("shadowgraph: headless on %s, %ux%u\n", context.device_name().c_str(), options.width,
              options.height);

  const BuiltinScene scene = make_builtin_scene();
  SceneRenderer renderer(context, scene);
  renderer.resize({options.width, options.height});
  vk::FrameRing frames(context);

  const uint32_t frame_count = options.frames.value_or(3);
  std::vector<double> frame_ms;
  for (uint32_t i = 0; i < frame_count; ++i) {
    const auto start = std::chrono::steady_clock::now();
    vk::FrameSlot& frame = frames.begin_frame();
    renderer.record(frame.cmd, scene.camera, scene.lens);
    frames.submit();
    frame_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  frames.wait_idle();
  return finish_run(options, context, renderer, frame_ms);
}

}  // namespace sg::sandbox
