// SPDX-License-Identifier: MIT
#pragma once
// A debug view: how many lights each 16x16 screen tile shades, as color over the picture, read
// from light culling's lists (LightTiles::ranges). Like the depth overlay, a pass no engine
// file knows.
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/lighting/light_tiles_pass.h"

namespace sg::sandbox {

class LightHeatmapPass {
 public:
  LightHeatmapPass(vk::VulkanContext& context, rg::Format color_format);

  // Draws over `color` (the frame) and returns its new version. `scene`: the image the tiles were
  // culled for (the frame's depth), which the frame's render scale may make smaller than `color`.
  rg::ImageHandle add_to(rg::RenderGraph& graph, const LightTiles& tiles, rg::ImageHandle scene,
                         rg::ImageHandle color) const;

 private:
  vk::PipelineLayout layout_;
  vk::UniquePipeline pipeline_;
};

}  // namespace sg::sandbox
