// SPDX-License-Identifier: MIT
#pragma once
// Tiled deferred lighting: the lit sum starts from the ambient term and the background (a
// compute pass, shaders/lighting_ambient.comp, or the G-buffer pass itself: LitSumStart), then
// for each light group that has lights one pass with that group's shadow code compiled in
// (shaders/tiled_lighting.comp), over the tiles that have lights of the group (an indirect
// dispatch from LightTilesPass), adding them to the lit sum. Fragment passes over a quad per tile
// lost on both kinds of device (docs/PERFORMANCE.md) and are gone.
//
// Ranked filtering (filtered_lights > 0): before the groups, a pass finds at each pixel the
// weight of its filtered_lights-th heaviest light (shaders/lighting_filter_floor.comp); lighter
// lights take the hard test instead of their filter kernels, which bounds the kernels a pixel runs.
//
// Group sets (shaders/light_tiles_interface.glsl): where the culling runs an invocation per tile
// (CPU devices), tiles whose light groups are the same few groups of one light each are shaded by
// one pass holding those groups' code, which reads the G-buffer and the lit sum once for them all.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/background_pipelines.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/lighting/gbuffer_pass.h"
#include "systems/lighting/light_resources.h"
#include "systems/lighting/light_tiles_pass.h"
#include "systems/lighting/lighting_path.h"
#include "systems/lighting/shadow_probe.h"
#include "systems/shadows/frame_lights.h"
#include "systems/shadows/light_groups.h"

namespace sg {

class TiledLightingPass {
 public:
  // `start` automatic is resolved for the context's device (lit_sum_from_gbuffer() says how).
  // `filtered_lights`: at each pixel, the most lights that run their own filter kernels; 0: all.
  // `records`: how the shaders read the light records, automatic resolved for the device.
  explicit TiledLightingPass(vk::VulkanContext& context, LitSumStart start = LitSumStart::automatic,
                             uint32_t filtered_lights = 0,
                             LightRecordsIn records = LightRecordsIn::automatic);

  // Picks, and compiles when first needed, the pipeline of each group that has lights in
  // `lights` (sorted by group): each holds one algorithm's shadow code and only the code of the
  // light types the group has this frame (LIGHT_TYPES), for `view`; a group with a single light
  // reads no light lists (SINGLE_LIGHT). With `group_sets`, also picks the frame's group sets,
  // those that spare the most passes over the tiles an earlier frame counted (`tiles`), and
  // builds their pipelines as `builds` says: in the background, once a set has been picked
  // frames_before_background_build frames in a row, and a set whose pipeline is not built yet is
  // left out of the frame (its tiles take their groups' passes). add_to uses them.
  void prepare(const shadows::FrameLights& lights, LightingView view, bool group_sets = false,
               const TilesByGroups& tiles = {}, PipelineBuilds builds = PipelineBuilds::in_frame);

  // Waits until the group sets' pipelines asked for are built: the next frame that picks them
  // takes them all.
  void wait_for_pipeline_builds() { pipelines_by_set_->wait(); }

  // In the background, a set is built once picked this many frames in a row: a run of a few
  // frames, or a camera sweeping past, starts no builds it would not use.
  static constexpr uint32_t frames_before_background_build = 8;

  // This frame's group sets, for the culling to list tiles by (LightTilesPass::add_to).
  const GroupSets& group_sets() const { return group_sets_; }

  static constexpr rg::Format lit_sum_format = GBuffer::lit_sum_format;

  // Adds the ambient pass, which creates the lit sum (unless the G-buffer pass started it:
  // GBuffer::lit_sum, which lit_sum_from_gbuffer() requires), the filter floor's pass where
  // filtering is ranked and the view lit, and one pass per group with lights
  // in the last prepare(); returns the lit sum's newest version. `lights`, the records prepare() saw,
  // must live until the frame is recorded. Positions come from the depth buffer through the
  // camera's `view_projection`; `ambient` is the ambient term kA * IA per channel.
  rg::ImageHandle add_to(rg::RenderGraph& graph, const GBuffer& gbuffer, const LightTiles& tiles,
                         rg::ImageHandle atlas, const vk::Buffer& lights, const glm::mat4& view_projection,
                         const glm::vec3& camera_position, const glm::vec3& ambient) const;

  // Whether the G-buffer pass must start the lit sum (GBufferPass's writes_lit_sum), the
  // ambient pass then left out (LitSumStart, lighting_path.h).
  bool lit_sum_from_gbuffer() const { return lit_sum_from_gbuffer_; }

  uint32_t filtered_lights() const { return filtered_lights_; }

  // From the next prepare() on, each frame also records its lights' shadows into `probe`
  // (shadow_probe.h), after the light groups' passes; null: no more. The probe must outlive the
  // frames that write it.
  void probe_shadows(const ShadowProbe* probe) { probe_ = probe; }

  // At most 16: the floor pass keeps that many weights a pixel.
  static constexpr uint32_t most_filtered_lights = 16;

 private:
  vk::VulkanContext& context_;
  bool lit_sum_from_gbuffer_;
  LightResources light_resources_;
  // shaders/tiled_lighting.comp's variant for the light records and, reading them from storage,
  // the device's subgroups.
  std::span<const uint32_t> group_shader_;
  vk::UniqueSampler nearest_;  // G-buffer reads
  vk::PipelineLayout ambient_layout_;
  vk::UniquePipeline ambient_pipeline_;  // unless the G-buffer starts the lit sum
  vk::PipelineLayout layout_;
  uint32_t filtered_lights_;
  vk::UniquePipeline filter_floor_pipeline_;  // where filtered_lights_ > 0
  bool ranked_ = false;                       // this frame: filtered_lights_ > 0 and the view lit
  const ShadowProbe* probe_ = nullptr;
  bool probing_ = false;                               // this frame: a probe and the view lit
  std::array<vk::UniquePipeline, 2> probe_pipelines_;  // by ranked_, made when first needed
  // By group | light types << 8 | LightingView << 16 | single light << 24 | ranked << 25 |
  // contact shadows << 26.
  std::unordered_map<uint32_t, vk::UniquePipeline> pipelines_;
  // This frame's, by group; null for a group without lights.
  std::array<VkPipeline, shadows::light_group_count> current_{};
  // This frame's first record of each group: the group's light where it has one (SINGLE_LIGHT).
  std::array<uint32_t, shadows::light_group_count> group_light_{};
  // This frame's group sets (0: none) and their pipelines; the pipelines by set | types << 11 |
  // LightingView << 41 | ranked << 42.
  GroupSets group_sets_{};
  std::array<VkPipeline, tiles::LIGHT_GROUP_SETS> set_pipelines_{};
  std::unique_ptr<vk::BackgroundPipelines> pipelines_by_set_;  // on the heap: its thread holds it
  // The sets picked last frame, by pipeline key, and the frames in a row each was picked.
  struct ChosenSet {
    uint64_t key = 0;
    uint32_t frames = 0;
  };
  std::array<ChosenSet, tiles::LIGHT_GROUP_SETS> sets_chosen_{};
  // choose_group_sets' working storage, kept so that a frame allocates nothing: the combinations of
  // groups tiles had and their tiles, and the sets they could take.
  std::vector<std::pair<uint32_t, uint32_t>> counted_groups_;
  std::vector<uint32_t> candidate_sets_;
  void choose_group_sets(const shadows::FrameLights& lights, const TilesByGroups& tiles);
  // Chooses the frame's group sets (sets_chosen_, built or not), asks for their pipelines as
  // `builds` says and keeps those built (group_sets_, set_pipelines_).
  void take_group_sets(const shadows::FrameLights& lights, LightingView view, const TilesByGroups& tiles,
                       PipelineBuilds builds);
};

}  // namespace sg
