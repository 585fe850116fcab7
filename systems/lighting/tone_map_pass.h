// SPDX-License-Identifier: MIT
#pragma once
// Exposure and tone mapping (shaders/tone_map.glsl) as a render-graph pass: the lit sum of
// either lighting path into the displayable frame. The curve is the identity below its knee, so
// a scene lit within range looks as the lighting model computes it; brighter colors are
// compressed towards 1 instead of clipping.
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"

namespace sg {

class ToneMapPass {
 public:
  ToneMapPass(vk::VulkanContext& context, rg::Format output_format);

  // Reads `lit_sum`, writes all of `output` (same size) and returns `output`'s new version.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle lit_sum, rg::ImageHandle output,
                         float exposure) const;

 private:
  vk::PipelineLayout layout_;
  vk::UniquePipeline pipeline_;
};

}  // namespace sg
