#pragma once
// The G-buffer of tiled deferred lighting (shaders/gbuffer.frag): every drawable of the GpuScene
// rasterized once into what the lighting needs per pixel. All targets are transients of the
// frame's size.
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
class GpuTextures;

struct GBuffer {
  rg::ImageHandle normal;  // rgba16f: unit normal, shininess
  rg::ImageHandle albedo;  // rgba8: base colour, specular strength
  rg::ImageHandle depth;   // D32: 1 where no surface was drawn; world positions come back from it
};

class GBufferPass {
 public:
  // `textures` must outlive the pass: its array is bound once.
  GBufferPass(vk::VulkanContext& context, uint32_t frames_in_flight, const GpuTextures& textures);

  // Points the slot's descriptor set at this frame's instances.
  void prepare(uint32_t slot, const GpuScene& scene);

  GBuffer add_to(rg::RenderGraph& graph, uint32_t width, uint32_t height, const GpuScene& scene,
                 uint32_t slot, const FrameConstants& constants) const;

 private:
  vk::PipelineLayout layout_;
  vk::DescriptorSets slot_sets_;
  vk::UniquePipeline pipeline_;
};

}  // namespace sg
