// SPDX-License-Identifier: MIT
#pragma once
// The batch's pairs rasterized with the hardware (shadows::ShadowRaster::hardware), after the
// cull (shadow_cull_pass.h):
//
//   shadow scatter   (compute)  the pairs sorted into the draws' instance ranges
//   shadow views     (raster)   clears the views' tiles, then two multi-draw indirect calls
//                               (2D maps depth only; cube faces with shadow_cube.frag) draw
//                               every pair into its tile of its atlas layer
//
// It draws every caster into every view and keeps no static layers. It needs shaderOutputLayer
// (gl_Layer from the vertex stage, shaders/shadow_batch.vert).
#include <vector>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/shadow_maps/shadow_batch_records.h"
#include "systems/shadow_maps/shadow_cull_pass.h"

namespace sg {

class GpuTextures;

class HardwareShadowRaster {
 public:
  // `textures`: the materials' (cut-out casters read their alpha), kept by reference.
  HardwareShadowRaster(vk::VulkanContext& context, const GpuTextures& textures);

  // The cut-out casters' pipelines (shaders/shadow_cut_out.glsl), made with the first scene that
  // has such casters; later calls do nothing.
  void make_cut_out_pipelines();

  // Before add_to, on a frame it draws: the clears of `frame`'s tiles, kept for the pass to record
  // (the list's storage kept from frame to frame).
  void prepare(const ShadowBatchFrame& frame);

  // Adds the passes that draw `culled` into `frame`'s tiles of `atlas` and returns the atlas's
  // newest version. Without pairs (CulledPairs{}, a frame without casters) the tiles are only
  // cleared. `scene` is read when the passes record.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle atlas, const ShadowBatchFrame& frame,
                         const CulledPairs& culled, const GpuScene& scene, uint32_t slot) const;

 private:
  // For opaque casters or cut-out ones.
  struct Pipelines {
    vk::UniquePipeline map;   // shadow_batch.vert
    vk::UniquePipeline face;  // shadow_batch.vert, shadow_cube.frag
  };
  Pipelines make_pipelines(bool cut_out) const;

  vk::VulkanContext& context_;
  const GpuTextures& textures_;
  vk::PipelineLayout scatter_layout_;
  vk::PipelineLayout raster_layout_;
  vk::UniquePipeline scatter_pipeline_;
  Pipelines opaque_;
  Pipelines cut_out_;
  std::vector<VkClearRect> clears_;  // this frame's, by view: its tile cleared to the far plane
};

}  // namespace sg
