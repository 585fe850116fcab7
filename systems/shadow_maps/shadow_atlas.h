// SPDX-License-Identifier: MIT
#pragma once
// The persistent shadow storage every light shares: one D32 2D-array image whose layers are the
// atlas pages (shadows/shadow_atlas_shape.h). A 2D shadow is one square tile of a page, a point
// light's cube six tiles of one page; shadows::ShadowAtlasPlanner says which. The image outlives
// frames and is imported into each frame's graph.
//
// Where the compute raster keeps static layers (ShadowViewBatch), a buffer of floats holds one
// for every tile, laid out as the pages are: the depths of the casters that do not move, kept
// from a map's last drawing with every caster, so that moving casters alone are drawn over them.
//
// Contract: fit() recreates the image (and buffer) only to hold more pages than it has (never
// fewer, never more than the shape's max_pages); recreating waits for the GPU to go idle first,
// because frames in flight may still sample the old image, and loses every tile's contents. The
// image always exists (at least one page), so the lighting passes' descriptors are always valid.
#include <cstdint>

#include "rendergraph/core/resource_types.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "systems/shadows/shadow_atlas_shape.h"

namespace sg {

class GpuTextures;

class ShadowAtlas {
 public:
  static constexpr rg::Format depth_format = rg::Format::d32_sfloat;

  // `budget_bytes` 0: the device's default (shadows::default_shadow_budget); it pays for the
  // static layers too when there are (`static_layers`).
  ShadowAtlas(vk::VulkanContext& context, uint64_t budget_bytes, bool static_layers);

  // Makes room for `pages` pages (at most shape().max_pages). True when the image was recreated.
  bool fit(uint32_t pages);

  const vk::Image& image() const { return image_; }
  // The static layers: texel (x, y) of page p at p * page_size^2 + y * page_size + x; null
  // without them.
  const vk::Buffer* static_layers() const { return static_layers_.handle() ? &static_layers_ : nullptr; }
  const shadows::AtlasShape& shape() const { return shape_; }
  uint32_t pages() const { return pages_; }
  // Memory of the image and static layers, for --stats' shadow_map_bytes.
  uint64_t bytes() const;
  // What a texel of a page costs: its depth in the image, and in the static layers if kept.
  uint32_t texel_bytes() const;

 private:
  vk::VulkanContext& context_;
  bool keeps_static_layers_;
  shadows::AtlasShape shape_;
  uint32_t pages_ = 0;
  vk::Image image_;
  vk::Buffer static_layers_;
};

// What the device allows the atlas.
shadows::DeviceShadowLimits shadow_limits(const vk::VulkanContext& context);

// A pipeline that draws casters into the atlas with `layout` (positions only, depth in
// depth_format, both faces); callers add their shaders.
vk::GraphicsPipelineDesc shadow_pipeline_desc(VkPipelineLayout layout);
// The same for the shaders' cut_out variants (shaders/shadow_cut_out.glsl), which read the uv
// too and sample `textures` where it has images.
vk::GraphicsPipelineDesc shadow_cut_out_pipeline_desc(VkPipelineLayout layout, const GpuTextures& textures);

}  // namespace sg
