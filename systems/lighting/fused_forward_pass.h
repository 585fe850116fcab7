// SPDX-License-Identifier: MIT
#pragma once
// Forward lighting and tone mapping in one pass (shaders/scene_fused.frag), for frames of a few
// lights: after a depth prepass (DepthPrepass), every drawable shaded once with every light of
// the frame, no light lists, and the tone-mapped picture written into the frame. The pipeline is
// specialized on the light groups the frame has, so it holds only their shadow code; one is
// compiled per set of groups (and view), when first needed. A pixel pays for every light, each
// with its own group's code, so this suits a handful of lights, on CPU devices where each
// full-screen pass costs milliseconds (LightingPath::fused).
#include <array>
#include <cstdint>
#include <unordered_map>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "systems/gpu/scene_gpu_types.h"
#include "systems/lighting/camera_pipelines.h"
#include "systems/lighting/light_resources.h"
#include "systems/lighting/lighting_path.h"
#include "systems/shadows/light_groups.h"

namespace sg {

class GpuScene;
class GpuTextures;

struct FusedTargets {
  rg::ImageHandle frame;  // the picture
  rg::ImageHandle depth;  // the prepass's depth, tested (not written) by the pass
};

class FusedForwardPass {
 public:
  // `frame_format`: the format of the images add_to draws into. `textures` must outlive the pass.
  FusedForwardPass(vk::VulkanContext& context, const GpuTextures& textures, rg::Format frame_format);

  // Makes the pipelines for the frame's light groups (shadows::groups_present), `view` and the
  // draw classes `scene` has.
  void prepare(const shadows::GroupsPresent& groups, LightingView view, const GpuScene& scene);

  // Shades every drawable where the prepass left it and writes the picture, exposed by
  // `exposure` and tone mapped, into all of `frame`; returns the new versions. `lights` and
  // `scene` are read when the pass records.
  FusedTargets add_to(rg::RenderGraph& graph, rg::ImageHandle depth, rg::ImageHandle frame,
                      rg::ImageHandle atlas, const vk::Buffer& lights, const GpuScene& scene, uint32_t slot,
                      FrameConstants constants, float exposure) const;

 private:
  vk::VulkanContext& context_;
  const GpuTextures& textures_;
  rg::Format frame_format_;
  LightResources light_resources_;
  vk::PipelineLayout layout_;
  std::unordered_map<uint64_t, CameraPipelines> pipelines_;  // by GroupsPresent::key and view
  uint64_t key_ = 0;                                         // this frame's
};

}  // namespace sg
