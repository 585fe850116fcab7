// SPDX-License-Identifier: MIT
#pragma once
// Which casters each shadow view draws. A light can only shadow what lies within its reach, so
// every view keeps the casters whose world bounds meet the light's sphere of range (spot and
// point lights; directional and cylinder views keep every caster). The kept instances' indices
// go into one id buffer per frame slot, and each view gets one indirect command per mesh
// whose firstInstance points into that buffer: the shadow shaders read
// instances[view_instances[gl_InstanceIndex]] (shaders/shadow_map.vert).
//
// Bounded views do not test every caster: begin_frame() bins the casters into a uniform grid
// over the scene's ground plane (x, z), and a view tests only the casters in the cells its
// sphere covers, so culling costs follow what lights reach, not lights times casters.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "systems/scene/layers.h"

namespace sg {

class GpuScene;

struct CasterView {
  uint32_t first_command = 0;
  uint32_t command_count = 0;
  // The last of them: masked or transparent casters' groups (GpuScene::first_cut_out_group),
  // drawn with the shaders' cut_out variants.
  uint32_t cut_out_commands = 0;
};

class ShadowCasterLists {
 public:
  ShadowCasterLists(vk::VulkanContext& context, uint32_t frames_in_flight);

  // Starts a frame's lists for the scene as GpuScene::update left it. `typical_reach` (the
  // bounded views' mean radius) sizes the grid's cells, so that a view covers a few cells.
  void begin_frame(const GpuScene& scene, float typical_reach);
  // The casters of `scene` on a layer of `caster_mask` whose bounds meet the sphere `reach` (xyz
  // centre, w radius; a negative radius keeps every one), each drawn `copies` times (6 for
  // layered cubes). A transparent caster whose bounds hold the centre, the light, is left out: a
  // light inside a glass bulb or a marker is not shut in by it.
  CasterView add_view(const GpuScene& scene, const glm::vec4& reach, scene::LayerMask caster_mask,
                      uint32_t copies);
  // Writes the frame's ids and commands to the slot's buffers (after the last add_view).
  void upload(uint32_t slot);

  const vk::Buffer& ids(uint32_t slot) const { return ids_.buffer(slot); }
  // Draws the opaque casters of `view`, or with `cut_out` its cut-out ones, with the pipeline
  // bound and the scene's geometry bound.
  void draw(VkCommandBuffer cmd, uint32_t slot, CasterView view, bool cut_out) const;

  // Instances kept over all views of the frame, before copies: what culling left to draw.
  uint64_t kept_instances() const { return ids_scratch_.size(); }

 private:
  // The frame's grid: cell c holds caster ids cell_ids[cell_start[c] .. cell_start[c + 1]).
  struct Grid {
    glm::vec2 origin{0.0f};
    float cell_size = 1.0f;
    uint32_t columns = 0;
    uint32_t rows = 0;
    std::vector<uint32_t> cell_start;
    std::vector<uint32_t> cell_ids;
  };
  void build_grid(const GpuScene& scene, float typical_reach);

  vk::FrameBuffers ids_;
  vk::FrameBuffers commands_;
  Grid grid_;
  std::vector<uint32_t> group_of_;  // per instance: its caster group, or none
  std::vector<uint32_t> seen_;      // per instance: the last view that tested it
  uint32_t view_stamp_ = 0;
  std::vector<uint32_t> candidates_;             // one view's kept ids
  std::vector<std::vector<uint32_t>> by_group_;  // the same, per caster group
  std::vector<uint32_t> ids_scratch_;
  std::vector<VkDrawIndexedIndirectCommand> commands_scratch_;
};

}  // namespace sg
