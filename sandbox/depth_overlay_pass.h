// SPDX-License-Identifier: MIT
#pragma once
// The render graph's extension example: a pass written outside the engine (no file in
// rendergraph/ or systems/ knows it) that draws the camera's depth buffer, as grey, into the
// bottom-right quarter of the frame. rendergraph/README.md walks through it.
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/scene/camera.h"

namespace sg::sandbox {

class DepthOverlayPass {
 public:
  DepthOverlayPass(vk::VulkanContext& context, rg::Format color_format);

  // Reads `depth` (a D32 depth buffer rendered with `lens`), draws over `color`, and returns
  // `color`'s new version.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle depth, rg::ImageHandle color,
                         const scene::Camera& lens) const;

 private:
  vk::UniqueSampler sampler_;
  vk::PipelineLayout layout_;
  vk::UniquePipeline pipeline_;
};

}  // namespace sg::sandbox
