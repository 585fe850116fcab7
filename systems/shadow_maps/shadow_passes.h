// SPDX-License-Identifier: MIT
#pragma once
// The per-light shadow passes, the baseline ShadowViewBatch is measured against
// (--shadow-views per-light): one pass per 2D shadow (spot, directional, cylinder light) due this
// frame, drawing into that light's atlas tile, and per point-light shadow either one pass for all
// six faces (shadows::CubeShadowMode::layered: shadow_cube_layered.vert moves each face into its
// tile) or six passes, one per face. Each pass clears its tiles and keeps the rest of the atlas
// layer. Every pass draws the casters within its light's reach (ShadowCasterLists, culled on the
// CPU) with one indirect call.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/shadow_maps/shadow_caster_lists.h"
#include "systems/shadows/cube_shadow_mode.h"
#include "systems/shadows/frame_lights.h"

namespace sg {

class GpuTextures;

class ShadowPasses {
 public:
  // `textures`: the materials' (cut-out casters read their alpha), kept by reference.
  ShadowPasses(vk::VulkanContext& context, uint32_t frames_in_flight, const GpuTextures& textures);

  // CPU side of a frame, after FrameRing::begin_frame returned `slot`: culls the casters of each
  // view that renders (or, without cull_casters, gives every view every caster), writes them and
  // the point lights' faces (matrices and tiles in an atlas of `page_size` texels a page), and
  // points the slot's descriptor set at this frame's buffers. `mode` must be the one add_to gets.
  void prepare(uint32_t slot, const shadows::FrameLights& lights, const GpuScene& scene, uint32_t page_size,
               shadows::CubeShadowMode mode, bool cull_casters = true);

  // Adds the passes of the views of `lights` (as given to prepare) that render, and returns the
  // atlas's newest version. `lights` and `scene` are read when the passes record.
  //
  // kept_casters() says how many caster instances the views kept after culling.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle atlas, const shadows::FrameLights& lights,
                         const GpuScene& scene, uint32_t slot, shadows::CubeShadowMode mode) const;

  uint64_t kept_casters() const { return casters_.kept_instances(); }

 private:
  // A view's shaders, for opaque casters or for cut-out ones (shaders/shadow_cut_out.glsl).
  struct Pipelines {
    vk::UniquePipeline map;      // shadow_map.vert
    vk::UniquePipeline face;     // shadow_map.vert, shadow_cube.frag
    vk::UniquePipeline layered;  // shadow_cube_layered.vert, shadow_cube.frag
  };
  Pipelines make_pipelines(bool cut_out) const;
  // Draws `view`'s casters with `kind` of the opaque pipelines, then of the cut-out ones.
  void draw_casters(VkCommandBuffer cmd, uint32_t slot, vk::UniquePipeline Pipelines::*kind,
                    const glm::mat4& view_projection, const glm::vec4& position_far,
                    uint32_t cube_faces_offset, const GpuScene& scene, CasterView view) const;

  vk::VulkanContext& context_;
  const GpuTextures& textures_;
  vk::PipelineLayout layout_;
  vk::DescriptorSets slot_sets_;
  Pipelines opaque_;
  Pipelines cut_out_;  // made with the first scene that has cut-out casters
  ShadowCasterLists casters_;
  std::vector<CasterView> map_casters_;   // per shadows::FrameLights::maps entry (empty unless it renders)
  std::vector<CasterView> cube_casters_;  // per shadows::FrameLights::cubes entry
  vk::FrameBuffers cube_faces_;           // per point light: its CubeFaces block, at cube_faces_stride_
  VkDeviceSize cube_faces_stride_ = 0;
  std::vector<std::byte> cube_faces_scratch_;
};

}  // namespace sg
