// SPDX-License-Identifier: MIT
#pragma once
// The batch's pairs rasterized in compute (shadows::ShadowRaster::compute), after the cull
// (shadow_cull_pass.h):
//
//   shadow raster    (compute)  a workgroup per pair writes its triangles' depths into the
//                               views' squares of a depth buffer (shaders/shadow_raster.comp)
//   shadow copy      (transfer) the squares into their atlas tiles, in rectangles of
//                               16,384 texels or more
//   shadow copy draw (raster)   the views of smaller rectangles, two triangles each writing its
//                               depths (shaders/shadow_depth_copy.vert)
//
// Where each view's square lies, and which rectangles are copied, come from
// shadows::DepthPlacement.
//
// With static layers (the atlas's, ShadowAtlas; shadow_static_layers.h) it draws moving casters
// (GpuScene::moving) apart: a view drawn with every caster is culled against the still casters
// (pair list 0), rasterized, and its square saved as its static layer ("shadow static save")
// before the moving casters (list 1) are drawn over it ("shadow raster moving"); a view that only
// moving casters made wrong (ShadowMapView::moving_casters_only) starts from its static layer
// ("shadow static restore") and gets list 1 alone. A frame whose views are mostly redrawn for a
// few moving casters then draws those casters, not the scene.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/shadow_maps/shadow_batch_records.h"
#include "systems/shadow_maps/shadow_cull_pass.h"
#include "systems/shadow_maps/shadow_static_layers.h"
#include "systems/shadows/depth_placement.h"

namespace sg {

class GpuTextures;

class ComputeShadowRaster {
 public:
  // `with_pipelines`: the batch's frames may rasterize in compute; without, it makes no pipelines
  // and only places views' depths nowhere, for the hardware raster's frames. `textures`: the
  // materials' (cut-out casters read their alpha), kept by reference.
  ComputeShadowRaster(vk::VulkanContext& context, const GpuTextures& textures, bool with_pipelines);
  bool has_pipelines() const { return static_cast<bool>(pipeline_); }

  // The cut-out casters' pipeline (shaders/shadow_cut_out.glsl), made with the first scene that
  // has such casters; later calls do nothing, as do calls without pipelines.
  void make_cut_out_pipeline();

  // Where the views of `tiles` put their depths, for a frame it rasterizes; the places, copied
  // rectangles and drawn views of the last call stand while the tiles are the same.
  void place_depths(std::span<const shadows::AtlasTile> tiles);
  // `views` views placed nowhere, for a frame the hardware rasterizes.
  void place_nowhere(size_t views) { placement_.place_nowhere(views); }
  // Per view: where its square's texel (0, 0) is in the depth buffer, and the row pitch there.
  std::span<const glm::uvec2> depth_places() const { return placement_.places(); }
  // The depth buffer's size, texels.
  uint64_t depth_texels() const { return placement_.texels(); }

  // Adds the passes that draw `culled` into `frame`'s tiles of `atlas` and returns the atlas's
  // newest version. `depths`: depth_texels() at the far plane (add_shadow_cull_reset).
  // `static_layers`: the atlas's, imported, when the frame is layered. `scene` is read when the
  // passes record.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle atlas, rg::BufferHandle depths,
                         rg::BufferHandle static_layers, const ShadowBatchFrame& frame,
                         const CulledPairs& culled, const GpuScene& scene, uint32_t slot) const;

 private:
  // Adds one list's raster pass; `depths` moves on to the version written.
  void add_raster(rg::RenderGraph& graph, const char* name, uint32_t list, const ShadowBatchFrame& frame,
                  const CulledPairs& culled, const GpuScene& scene, uint32_t slot,
                  rg::BufferHandle& depths) const;

  vk::VulkanContext& context_;
  const GpuTextures& textures_;
  vk::PipelineLayout layout_;
  vk::UniquePipeline pipeline_;
  vk::UniquePipeline cut_out_pipeline_;
  vk::PipelineLayout copy_layout_;
  vk::UniquePipeline copy_pipeline_;                 // "shadow copy draw"
  std::optional<ShadowStaticLayers> static_layers_;  // with the pipelines
  shadows::DepthPlacement placement_;
  std::vector<VkBufferImageCopy> copies_;  // placement_'s copied rectangles
};

}  // namespace sg
