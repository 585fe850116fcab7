// SPDX-License-Identifier: MIT
#pragma once
// Forward lighting: every drawable of the GpuScene shaded by ambient plus every light of the
// frame at every pixel, each light with its own shadow algorithm and parameters
// (shaders/scene.frag, shaders/light_shading.glsl), into a lit sum and a depth buffer it creates.
#include <cstdint>
#include <unordered_map>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "systems/gpu/scene_gpu_types.h"
#include "systems/lighting/camera_pipelines.h"
#include "systems/lighting/light_resources.h"
#include "systems/lighting/lighting_path.h"

namespace sg {

class GpuScene;
class GpuTextures;
class ShadowAtlas;

struct ForwardTargets {
  rg::ImageHandle lit_sum;  // linear HDR color, for tone mapping
  rg::ImageHandle depth;    // transient D32, readable by later passes (depth-tested or sampled)
};

class ForwardPass {
 public:
  // As the deferred path's: tone_map.frag reads the lit sum as an rgba16f storage image, and a
  // view of another format reads undefined values there (Debian 13's validation layer says so).
  static constexpr rg::Format lit_sum_format = rg::Format::rgba16_sfloat;

  // `textures` must outlive the pass: its array is bound once.
  ForwardPass(vk::VulkanContext& context, uint32_t frames_in_flight, const GpuTextures& textures);

  // CPU side of a frame, after FrameRing::begin_frame returned `slot`: points the slot's
  // descriptor set at this frame's instances, light records and shadow images, and makes the
  // pipelines for `view` and the scene's draw classes that it has not yet.
  void prepare(uint32_t slot, const GpuScene& scene, const vk::Buffer& lights,
               const ShadowAtlas& shadow_atlas, LightingView view);

  // Adds the pass: samples `atlas` (the shadow atlas's newest version), draws every
  // instance into a new lit sum and depth buffer of `width` x `height`. `scene` is read when the
  // pass records.
  ForwardTargets add_to(rg::RenderGraph& graph, uint32_t width, uint32_t height, rg::ImageHandle atlas,
                        const GpuScene& scene, uint32_t slot, const FrameConstants& constants) const;

 private:
  vk::VulkanContext& context_;
  const GpuTextures& textures_;
  LightResources light_resources_;
  vk::PipelineLayout layout_;
  vk::DescriptorSets slot_sets_;
  std::unordered_map<uint32_t, CameraPipelines> pipelines_;  // by LightingView
  LightingView view_ = LightingView::lit;
};

}  // namespace sg
