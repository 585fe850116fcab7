#pragma once
// The lighting pass: every drawable of the GpuScene shaded with the extended Blinn model
// (shaders/scene.frag) into a colour target, with a depth buffer it creates.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/vulkan/unique_handle.h"
#include "systems/scene_gpu_types.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg {

class GpuScene;

struct ForwardTargets {
  rg::ImageHandle colour;
  rg::ImageHandle depth;  // transient D32, readable by later passes (depth-tested or sampled)
};

class ForwardPass {
 public:
  static constexpr rg::Format colour_format = rg::Format::rgba8_srgb;
  static constexpr rg::Format depth_format = rg::Format::d32_sfloat;

  explicit ForwardPass(vk::VulkanContext& context);

  // Adds the pass: clears `colour` (a colour_format image of the frame's size) and a new depth
  // buffer, draws every instance. `scene` and `constants` are read when the pass records.
  ForwardTargets add_to(rg::RenderGraph& graph, rg::ImageHandle colour, const GpuScene& scene,
                        uint32_t slot, const FrameConstants& constants) const;

 private:
  vk::UniqueDescriptorSetLayout set_layout_;
  vk::UniquePipelineLayout pipeline_layout_;
  vk::UniquePipeline pipeline_;
};

}  // namespace sg
