// SPDX-License-Identifier: MIT
#pragma once
// The G-buffer of tiled deferred lighting (shaders/gbuffer.glsl): every drawable of the GpuScene
// rasterized once into what the lighting needs per pixel, and optionally the start of the lit
// sum too (shaders/gbuffer_lit_sum.frag), which otherwise a pass of its own writes
// (TiledLightingPass). All targets are transients of the frame's size.
#include <cstdint>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "systems/gpu/scene_gpu_types.h"
#include "systems/lighting/camera_pipelines.h"

namespace sg {

class GpuScene;
class GpuTextures;

struct GBuffer {
  rg::ImageHandle normal;  // rgba16f: unit normal, shininess
  rg::ImageHandle albedo;  // rgba8: base color, specular strength
  rg::ImageHandle depth;   // D32, reversed: 0 where no surface was drawn; world positions come back from it
  // The lit sum's start (of lit_sum_format): the ambient term times the base color, the
  // background color where no surface was drawn. Invalid unless the pass writes it.
  rg::ImageHandle lit_sum;
  // The deferred lit sum's format: this pass may start it, TiledLightingPass adds the lights.
  static constexpr rg::Format lit_sum_format = rg::Format::rgba16_sfloat;
};

class GBufferPass {
 public:
  // `textures` must outlive the pass: its array is bound once. With `writes_lit_sum` the pass
  // also starts the lit sum (GBuffer::lit_sum), from FrameConstants' ambient term.
  GBufferPass(vk::VulkanContext& context, uint32_t frames_in_flight, const GpuTextures& textures,
              bool writes_lit_sum = false);

  // Points the slot's descriptor set at this frame's instances, and makes the pipelines of the
  // draw classes the scene has.
  void prepare(uint32_t slot, const GpuScene& scene);

  GBuffer add_to(rg::RenderGraph& graph, uint32_t width, uint32_t height, const GpuScene& scene,
                 uint32_t slot, const FrameConstants& constants) const;

 private:
  vk::VulkanContext& context_;
  bool writes_lit_sum_;
  vk::PipelineLayout layout_;
  vk::DescriptorSets slot_sets_;
  CameraPipelines pipelines_;
};

}  // namespace sg
