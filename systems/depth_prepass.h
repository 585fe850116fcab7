#pragma once
// The depth prepass of the forward paths (shaders/depth_prepass.vert, no fragment shader): every
// drawable's depth into a new D32 image, so that the shading pass after it, testing LESS_OR_EQUAL
// without writing depth, shades each pixel once.
#include <cstdint>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/scene_gpu_types.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg {

class GpuScene;

class DepthPrepass {
 public:
  explicit DepthPrepass(vk::VulkanContext& context);

  // Adds the pass and returns the new depth image, `width` x `height`. `scene` is read when the
  // pass records.
  rg::ImageHandle add_to(rg::RenderGraph& graph, uint32_t width, uint32_t height, const GpuScene& scene,
                         uint32_t slot, const FrameConstants& constants) const;

 private:
  // Binds only the instances: a set with unwritten descriptors is not bindable.
  vk::PipelineLayout layout_;
  vk::UniquePipeline pipeline_;
};

}  // namespace sg
