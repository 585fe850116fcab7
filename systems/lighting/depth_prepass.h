// SPDX-License-Identifier: MIT
#pragma once
// The depth prepass of the forward paths: every drawable's depth into a new D32 image, so that
// the shading pass after it, testing for the same depth without writing it, shades each pixel
// once. Plain surfaces need no fragment shader (shaders/depth_prepass.vert); masked ones cut
// their holes (scene.vert and shaders/alpha_test.frag).
#include <cstdint>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "systems/gpu/scene_gpu_types.h"
#include "systems/lighting/camera_pipelines.h"

namespace sg {

class GpuScene;
class GpuTextures;

class DepthPrepass {
 public:
  // `textures` must outlive the pass.
  DepthPrepass(vk::VulkanContext& context, const GpuTextures& textures);

  // Makes the pipelines of the draw classes `scene` has.
  void prepare(const GpuScene& scene);

  // Adds the pass and returns the new depth image, `width` x `height`. `scene` is read when the
  // pass records.
  rg::ImageHandle add_to(rg::RenderGraph& graph, uint32_t width, uint32_t height, const GpuScene& scene,
                         uint32_t slot, const FrameConstants& constants) const;

 private:
  vk::VulkanContext& context_;
  const GpuTextures& textures_;
  vk::PipelineLayout layout_;
  CameraPipelines pipelines_;
};

}  // namespace sg
