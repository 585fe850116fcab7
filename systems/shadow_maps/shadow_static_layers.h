// SPDX-License-Identifier: MIT
#pragma once
// The compute raster's static layers (ShadowAtlas::static_layers, compute_shadow_raster.h): a
// view's depths copied between its square of the raster's depth buffer and its layer, a tile
// of a float buffer shaped like the atlas (shaders/shadow_static_layers.glsl):
//
//   shadow static save     (compute)  squares of views drawn with their still casters -> layers
//   shadow static restore  (compute)  layers of views drawn with moving casters alone -> squares
#include <cstdint>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/shadow_maps/shadow_batch_records.h"

namespace sg {

class ShadowStaticLayers {
 public:
  explicit ShadowStaticLayers(vk::VulkanContext& context);

  // Adds "shadow static save": the depths of `frame`'s views [first, first + count) into their
  // static layers. Returns the layers' version written.
  rg::BufferHandle add_save(rg::RenderGraph& graph, const ShadowBatchFrame& frame, uint32_t first,
                            uint32_t count, rg::BufferHandle depths, rg::BufferHandle layers) const;
  // Adds "shadow static restore": the same views' static layers into their depths. Returns the
  // depths' version written.
  rg::BufferHandle add_restore(rg::RenderGraph& graph, const ShadowBatchFrame& frame, uint32_t first,
                               uint32_t count, rg::BufferHandle depths, rg::BufferHandle layers) const;

 private:
  // Copies views [first, first + count) one way; `depths` and `layers` move on to the versions
  // written.
  void add_copy(rg::RenderGraph& graph, const char* name, bool save, const ShadowBatchFrame& frame,
                uint32_t first, uint32_t count, rg::BufferHandle& depths, rg::BufferHandle& layers) const;

  vk::PipelineLayout layout_;
  vk::UniquePipeline save_pipeline_;
  vk::UniquePipeline restore_pipeline_;
};

}  // namespace sg
