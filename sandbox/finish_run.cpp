#include <algorithm>
#include <cstdio>

#include "rendergraph/vulkan/context.h"
#include "rendergraph/vulkan/readback.h"
#include "sandbox/png.h"
#include "sandbox/run.h"
#include "systems/scene_renderer.h"

namespace sg::sandbox {

int finish_run(const Options& options, vk::VulkanContext& context, const SceneRenderer& renderer,
               const std::vector<double>& frame_ms) {
  if (!options.screenshot.empty() && frame_ms.empty()) {
    std::printf("shadowgraph: no frame was rendered, so no screenshot was written\n");
  } else if (!options.screenshot.empty()) {
    write_png(options.screenshot, vk::read_rgba8(context, renderer.color_target()));
    std::printf("shadowgraph: wrote %s\n", options.screenshot.c_str());
  }
  if (!frame_ms.empty()) {
    std::vector<double> sorted = frame_ms;
    std::sort(sorted.begin(), sorted.end());
    std::printf("shadowgraph: %zu frames, CPU frame time median %.2f ms (min %.2f, max %.2f)\n",
                sorted.size(), sorted[sorted.size() / 2], sorted.front(), sorted.back());
  }
  const vk::MemoryStats memory = context.allocator().stats();
  std::printf("shadowgraph: GPU memory %.1f MiB used in %u blocks (%.1f MiB reserved)\n",
              double(memory.used_bytes) / (1 << 20), memory.block_count,
              double(memory.reserved_bytes) / (1 << 20));
  if (context.validation_enabled()) {
    std::printf("shadowgraph: validation errors: %u\n", context.validation_errors());
    if (context.validation_errors() > 0) return 3;
  }
  return 0;
}

}  // namespace sg::sandbox
