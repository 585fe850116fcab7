// SPDX-License-Identifier: MIT
#pragma once
// A pass of this program's own, added to the engine's frame through a FrameExtension: distance
// fog over the left half of the picture, from the camera's depth buffer. Nothing in the engine
// knows it; rendergraph/README.md ("Passes from outside the engine") walks through it.
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/scene/camera.h"

namespace custom_pass {

class FogPass {
 public:
  FogPass(sg::vk::VulkanContext& context, sg::rg::Format color_format);

  // Reads `depth` (the frame's depth buffer, rendered with `lens`), blends fog over the left
  // half of `color`, and returns `color`'s new version.
  sg::rg::ImageHandle add_to(sg::rg::RenderGraph& graph, sg::rg::ImageHandle depth, sg::rg::ImageHandle color,
                             const sg::scene::Camera& lens) const;

 private:
  sg::vk::UniqueSampler sampler_;
  sg::vk::PipelineLayout layout_;
  sg::vk::UniquePipeline pipeline_;
};

}  // namespace custom_pass
