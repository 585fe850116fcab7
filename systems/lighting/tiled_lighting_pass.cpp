// SPDX-License-Identifier: MIT
#include "systems/lighting/tiled_lighting_pass.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "shaders/lighting_ambient.comp.spv.h"
#include "shaders/lighting_filter_floor.comp.spv.h"
#include "shaders/lighting_filter_floor_storage_records.comp.spv.h"
#include "shaders/shadow_probe.comp.spv.h"
#include "shaders/shadow_probe_storage_records.comp.spv.h"
#include "shaders/tiled_lighting.comp.spv.h"
#include "shaders/tiled_lighting_set.comp.spv.h"
#include "shaders/tiled_lighting_set_storage_records.comp.spv.h"
#include "shaders/tiled_lighting_storage_records.comp.spv.h"
#include "shaders/tiled_lighting_warp_lists.comp.spv.h"
#include "systems/gpu/scene_gpu_types.h"
#include "systems/gpu/shader_bindings.h"

namespace sg {
namespace {

using namespace bindings;
constexpr VkShaderStageFlags compute_stage = VK_SHADER_STAGE_COMPUTE_BIT;

struct AmbientConstants {
  glm::vec4 background;  // rgb: the background color
  glm::vec4 ambient;     // rgb: the ambient term
  glm::uvec4 screen;     // width, height
};

// shaders/tiled_lighting_frame.glsl's push constants.
struct LightingConstants {
  glm::mat4 inverse_view_projection;
  glm::vec4 camera_position;
  glm::uvec4 screen;  // width, height, tiles across, tiles in all
  glm::uvec4 lights;  // x: a single-light group's light (SINGLE_LIGHT); a group set's, in group order
  glm::uvec4 set;     // x: a group set's place among the frame's sets
};
static_assert(tiles::LIGHT_GROUPS_A_SET <= 4, "a group set's lights are one uvec4");

std::string group_name(uint32_t group) {
  switch (shadows::group_shadow_kind(group)) {
    case shadows::ShadowKind::none: return "unshadowed";
    case shadows::ShadowKind::map: return "2d " + std::string(to_string(shadows::group_algorithm(group)));
    case shadows::ShadowKind::cube: return "cube " + std::string(to_string(shadows::group_algorithm(group)));
  }
  return "group " + std::to_string(group);
}

// The groups of group set `set` (bit g for group g), joined: "2d pcf + cube hard".
std::string set_name(uint32_t set) {
  std::string name;
  for (uint32_t group = 0; group < shadows::light_group_count; ++group) {
    if ((set >> group & 1u) != 0) name += (name.empty() ? "" : " + ") + group_name(group);
  }
  return name;
}

LightingConstants with_group_light(LightingConstants constants, uint32_t light) {
  constants.lights.x = light;
  return constants;
}

// The constants of group set `set`, at place `place` among the frame's, whose groups' lights are
// `group_light` (one a group).
LightingConstants with_set(LightingConstants constants, uint32_t set, uint32_t place,
                           const std::array<uint32_t, shadows::light_group_count>& group_light) {
  uint32_t k = 0;
  for (uint32_t group = 0; group < shadows::light_group_count; ++group) {
    if ((set >> group & 1u) != 0) constants.lights[int(k++)] = group_light[group];
  }
  constants.set.x = place;
  return constants;
}

// A shader's SPIR-V for where the pass reads the light records: its storage_records variant from
// a storage buffer.
std::span<const uint32_t> for_records(LightRecordsIn records, std::span<const uint32_t> texel_buffer,
                                      std::span<const uint32_t> storage_buffer) {
  return records == LightRecordsIn::storage_buffer ? storage_buffer : texel_buffer;
}

// Whether the device's subgroups take shaders/tiled_lighting.comp's warp_lists variant: 32 lanes
// or fewer (a ballot's first word), which ballot, shuffle and reduce in compute shaders.
bool subgroups_cull_lists(const vk::VulkanContext& context) {
  VkPhysicalDeviceSubgroupProperties subgroups{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroups};
  vkGetPhysicalDeviceProperties2(context.physical_device(), &properties);
  constexpr VkSubgroupFeatureFlags needed =
      VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_SHUFFLE_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
  return subgroups.subgroupSize <= 32 && (subgroups.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) != 0 &&
         (subgroups.supportedOperations & needed) == needed;
}

bool starts_in_gbuffer(LitSumStart start, const vk::VulkanContext& context) {
  if (start != LitSumStart::automatic) return start == LitSumStart::gbuffer;
  return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
}

}  // namespace

TiledLightingPass::TiledLightingPass(vk::VulkanContext& context, LitSumStart start, uint32_t filtered_lights,
                                     LightRecordsIn records)
    : context_(context),
      lit_sum_from_gbuffer_(starts_in_gbuffer(start, context)),
      light_resources_(context, records),
      group_shader_(light_resources_.records() == LightRecordsIn::storage_buffer &&
                            subgroups_cull_lists(context)
                        ? tiled_lighting_warp_lists_comp
                        : for_records(light_resources_.records(), tiled_lighting_comp,
                                      tiled_lighting_storage_records_comp)),
      nearest_(vk::create_sampler(context.device(), VK_FILTER_NEAREST)),
      ambient_layout_(context.device(),
                      {{gbuffer_albedo_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute_stage},
                       {scene_depth_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute_stage},
                       {hdr_binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, compute_stage}},
                      vk::push_constants<AmbientConstants>(compute_stage)),
      ambient_pipeline_(
          !lit_sum_from_gbuffer_
              ? vk::create_compute_pipeline(
                    context, {lighting_ambient_comp, {}, ambient_layout_.get(), "lighting ambient"})
              : vk::UniquePipeline{}),
      layout_(context.device(),
              LightResources::bindings(
                  light_resources_.records(), compute_stage,
                  {{scene_depth_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute_stage},
                   {gbuffer_normal_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute_stage},
                   {gbuffer_albedo_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute_stage},
                   {tile_lights_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute_stage},
                   {tile_ranges_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute_stage},
                   {group_tiles_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute_stage},
                   {hdr_binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, compute_stage},
                   {shadow_probe_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute_stage}}),
              vk::push_constants<LightingConstants>(compute_stage)),
      filtered_lights_(filtered_lights),
      pipelines_by_set_(std::make_unique<vk::BackgroundPipelines>(context)) {
  if (filtered_lights_ > most_filtered_lights) {
    throw std::invalid_argument("TiledLightingPass: at most " + std::to_string(most_filtered_lights) +
                                " filtered lights a pixel");
  }
  if (filtered_lights_ == 0) return;
  // constant_id 0 to 5 as a group pass's (every light type), 6: the lights a pixel filters.
  const std::vector<uint32_t> constants =
      light_resources_.specialized({0u, 0u, 0u, shadows::all_light_type_bits, 0u, 0u, filtered_lights_});
  filter_floor_pipeline_ = vk::create_compute_pipeline(
      context, {for_records(light_resources_.records(), lighting_filter_floor_comp,
                            lighting_filter_floor_storage_records_comp),
                constants, layout_.get(), "lighting filter floor"});
}

void TiledLightingPass::choose_group_sets(const shadows::FrameLights& lights, const TilesByGroups& tiles) {
  // A set's groups have one light each (its lights come as push constants) and no contact shadows
  // (which the set's pipeline would march for every group).
  uint32_t eligible = shadows::groups_present(lights.group_begin, lights.group_types).single;
  for (uint32_t group = 0; group < shadows::light_group_count; ++group) {
    if (lights.group_contact_lights[group] > 0) eligible &= ~(1u << group);
  }
  // The tiles' combinations of groups, and the sets they could take: their eligible groups.
  std::vector<std::pair<uint32_t, uint32_t>>& counted = counted_groups_;
  std::vector<uint32_t>& candidates = candidate_sets_;
  counted.clear();
  candidates.clear();
  for (uint32_t groups = 0; groups < tiles.size(); ++groups) {
    if (tiles[groups] == 0) continue;
    counted.emplace_back(groups, tiles[groups]);
    const uint32_t set = groups & eligible;
    if (std::popcount(set) >= 2 && std::popcount(set) <= int(tiles::LIGHT_GROUPS_A_SET))
      candidates.push_back(set);
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  // Greedily, the set that spares the most passes over tiles beyond the sets taken: a tile takes
  // the largest set among its groups (light_tile_lists.glsl's group_set_within), which spares a
  // pass per group of it but one.
  const auto largest_within = [&](uint32_t groups, size_t taken) {
    int most = 1;
    for (size_t s = 0; s < taken; ++s) {
      if ((group_sets_[s] & ~groups) == 0) most = std::max(most, std::popcount(group_sets_[s]));
    }
    return most;
  };
  for (size_t taken = 0; taken < group_sets_.size(); ++taken) {
    uint64_t best_spared = 0;
    uint32_t best = 0;
    for (const uint32_t set : candidates) {
      uint64_t spared = 0;
      for (const auto& [groups, count] : counted) {
        if ((set & ~groups) != 0) continue;
        spared += uint64_t{count} * uint64_t(std::max(std::popcount(set) - largest_within(groups, taken), 0));
      }
      if (spared > best_spared) {
        best_spared = spared;
        best = set;
      }
    }
    if (best == 0) break;
    group_sets_[taken] = best;
  }
}

void TiledLightingPass::prepare(const shadows::FrameLights& lights, LightingView view, bool group_sets,
                                const TilesByGroups& tiles, PipelineBuilds builds) {
  current_.fill(VK_NULL_HANDLE);
  // The shadow-only view shows each algorithm's own shade: every light filters there.
  ranked_ = filtered_lights_ > 0 && view == LightingView::lit;
  const uint32_t ranked = ranked_ ? 1u : 0u;
  probing_ = probe_ && view == LightingView::lit;
  if (probing_ && !probe_pipelines_[ranked]) {
    // constant_id 0 to 5 as a group pass's, with every light type and the view lit.
    const std::vector<uint32_t> constants =
        light_resources_.specialized({0u, 0u, 0u, shadows::all_light_type_bits, 0u, ranked});
    probe_pipelines_[ranked] = vk::create_compute_pipeline(
        context_,
        {for_records(light_resources_.records(), shadow_probe_comp, shadow_probe_storage_records_comp),
         constants, layout_.get(), "shadow probe"});
  }
  for (uint32_t group = 0; group < shadows::light_group_count; ++group) {
    const uint32_t types = lights.group_types[group];  // shadows::light_type_bits
    if (types == 0) continue;                          // no light of the group this frame
    const uint32_t first = lights.group_begin[group];
    const uint32_t single = lights.group_begin[group + 1] == first + 1 ? 1u : 0u;
    const uint32_t contact = lights.group_contact_lights[group] > 0 ? 1u : 0u;
    group_light_[group] = first;
    vk::UniquePipeline& pipeline = pipelines_[group | types << 8 | static_cast<uint32_t>(view) << 16 |
                                              single << 24 | ranked << 25 | contact << 26];
    current_[group] = pipeline.get();
    if (pipeline) continue;
    // constant_id 0: the group; 1: the view; 2: material.glsl's, unused here; 3: the light types;
    // 4: whether the group has a single light; 5: whether the lit sum's alpha holds the filter
    // floor; 6: the floor pass's, unused here; 7: whether a light of the group has contact shadows.
    const std::vector<uint32_t> constants = light_resources_.specialized(
        {group, static_cast<uint32_t>(view), 0u, types, single, ranked, 0u, contact});
    const std::string name = "tiled lighting " + group_name(group);
    pipeline = vk::create_compute_pipeline(context_, {group_shader_, constants, layout_.get(), name});
    current_[group] = pipeline.get();
  }
  group_sets_.fill(0);
  set_pipelines_.fill(VK_NULL_HANDLE);
  if (group_sets) {
    take_group_sets(lights, view, tiles, builds);
  } else {
    sets_chosen_ = {};
  }
}

void TiledLightingPass::take_group_sets(const shadows::FrameLights& lights, LightingView view,
                                        const TilesByGroups& tiles, PipelineBuilds builds) {
  const uint32_t ranked = ranked_ ? 1u : 0u;
  choose_group_sets(lights, tiles);
  std::array<uint64_t, tiles::LIGHT_GROUP_SETS> keys{};
  std::array<ChosenSet, tiles::LIGHT_GROUP_SETS> chosen{};
  uint32_t requested = 0;
  for (size_t s = 0; s < group_sets_.size() && group_sets_[s] != 0; ++s) {
    const uint32_t set = group_sets_[s];
    // Each group's light types, and together.
    const uint32_t group_types = shadows::packed_group_types(set, lights.group_types);
    uint32_t types = 0;
    for (uint32_t group = 0; group < shadows::light_group_count; ++group) {
      if ((set >> group & 1u) != 0) types |= lights.group_types[group];
    }
    keys[s] = set | uint64_t{group_types} << 11 | uint64_t{static_cast<uint32_t>(view)} << 41 |
              uint64_t{ranked} << 42;
    const auto before = std::find_if(sets_chosen_.begin(), sets_chosen_.end(),
                                     [&](const ChosenSet& earlier) { return earlier.key == keys[s]; });
    chosen[s] = {keys[s], before == sets_chosen_.end() ? 1u : before->frames + 1};
    if (pipelines_by_set_->asked(keys[s])) continue;
    if (builds == PipelineBuilds::background && chosen[s].frames < frames_before_background_build) continue;
    // As a group's (above), but shaders/tiled_lighting_set.comp, constant_id 6: the set's groups
    // (shadows::group_slot_list); 8: their light types.
    pipelines_by_set_->request(
        keys[s], {for_records(light_resources_.records(), tiled_lighting_set_comp,
                              tiled_lighting_set_storage_records_comp),
                  light_resources_.specialized({0u, static_cast<uint32_t>(view), 0u, types, 0u, ranked,
                                                shadows::group_slot_list(set), 0u, group_types}),
                  layout_.get(), "tiled lighting " + set_name(set)});
    ++requested;
  }
  if (requested > 0 && builds == PipelineBuilds::background) {
    std::printf(
        "shadowgraph: building %u group sets' lighting pipelines in the background; their tiles take "
        "a pass per light group until then\n",
        requested);
  }
  if (builds == PipelineBuilds::in_frame) pipelines_by_set_->wait();
  // The sets whose pipelines are built, in the order chosen; the others' tiles take their
  // groups' own passes this frame.
  size_t taken = 0;
  for (size_t s = 0; s < group_sets_.size() && group_sets_[s] != 0; ++s) {
    const VkPipeline pipeline = pipelines_by_set_->find(keys[s]);
    if (pipeline == VK_NULL_HANDLE) continue;
    group_sets_[taken] = group_sets_[s];
    set_pipelines_[taken++] = pipeline;
  }
  std::fill(group_sets_.begin() + std::ptrdiff_t(taken), group_sets_.end(), 0u);
  sets_chosen_ = chosen;
}

rg::ImageHandle TiledLightingPass::add_to(rg::RenderGraph& graph, const GBuffer& gbuffer,
                                          const LightTiles& tiles, rg::ImageHandle atlas,
                                          const vk::Buffer& lights, const glm::mat4& view_projection,
                                          const glm::vec3& camera_position, const glm::vec3& ambient) const {
  // A copy: declaring images may move the graph's resource list.
  const rg::ImageDesc screen = graph.resources()[gbuffer.albedo.index].image;
  const LightTileGrid grid = LightTileGrid::of(screen.width, screen.height);
  const LightingConstants constants{glm::inverse(view_projection),
                                    glm::vec4(camera_position, 0.0f),
                                    {screen.width, screen.height, grid.across, grid.count()},
                                    {}};
  rg::ImageHandle lit_sum = gbuffer.lit_sum;
  if (lit_sum_from_gbuffer_ != lit_sum.valid()) {
    throw std::logic_error(lit_sum_from_gbuffer_
                               ? "TiledLightingPass: the G-buffer must start the lit sum"
                               : "TiledLightingPass: the lit sum starts in the ambient pass");
  }
  if (!lit_sum.valid()) {
    graph.add_pass(
        "lighting ambient",
        [&](rg::PassBuilder& b) {
          b.read(gbuffer.albedo, rg::Usage::sampled_compute);
          b.read(gbuffer.depth, rg::Usage::sampled_compute);
          lit_sum = b.write(b.create_image("lit sum", {screen.width, screen.height, lit_sum_format}),
                            rg::Usage::storage_compute);
          return lit_sum;
        },
        [this, albedo = gbuffer.albedo, depth = gbuffer.depth,
         constants = AmbientConstants{glm::vec4(background_color, 0.0f),
                                      glm::vec4(ambient, 0.0f),
                                      {screen.width, screen.height, 0, 0}}](rg::ImageHandle lit_sum,
                                                                            const vk::PassRecorder& rec) {
          const VkDescriptorSet set =
              ambient_layout_.write(rec.allocate_set(ambient_layout_))
                  .image(gbuffer_albedo_binding, rec.view(albedo), nearest_.get())
                  .image(scene_depth_binding, rec.view(depth), nearest_.get())
                  .image(hdr_binding, rec.view(lit_sum), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL)
                  .update();
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, ambient_pipeline_.get());
          ambient_layout_.bind_compute(rec.cmd(), set);
          ambient_layout_.push(rec.cmd(), constants);
          vkCmdDispatch(rec.cmd(), (constants.screen.x + 15) / 16, (constants.screen.y + 15) / 16, 1);
        });
  }
  // Binds `pipeline` of layout_ with the lighting inputs, `lit_sum` and `constants`, and the
  // probe's buffer where given: the floor's pass, the groups' and the probe's.
  const auto bind = [this, gbuffer, tiles, atlas, &lights](
                        const vk::PassRecorder& rec, VkPipeline pipeline, rg::ImageHandle lit_sum,
                        const LightingConstants& constants, VkBuffer probe = VK_NULL_HANDLE) {
    const VkSampler nearest = nearest_.get();
    vk::DescriptorWriter writer = layout_.write(rec.allocate_set(layout_));
    writer.image(scene_depth_binding, rec.view(gbuffer.depth), nearest)
        .image(gbuffer_normal_binding, rec.view(gbuffer.normal), nearest)
        .image(gbuffer_albedo_binding, rec.view(gbuffer.albedo), nearest)
        .buffer(tile_lights_binding, rec.buffer(tiles.lights))
        .buffer(tile_ranges_binding, rec.buffer(tiles.ranges))
        .buffer(group_tiles_binding, rec.buffer(tiles.tiles))
        .image(hdr_binding, rec.view(lit_sum), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL);
    if (probe != VK_NULL_HANDLE) writer.buffer(shadow_probe_binding, probe);
    const VkDescriptorSet set = light_resources_.write(writer, lights, rec, atlas).update();
    vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    layout_.bind_compute(rec.cmd(), set);
    layout_.push(rec.cmd(), constants);
  };
  const auto read_lighting_inputs = [&](rg::PassBuilder& b) {
    for (const rg::ImageHandle image : {atlas, gbuffer.depth, gbuffer.normal, gbuffer.albedo}) {
      b.read(image, rg::Usage::sampled_compute);
    }
    for (const rg::BufferHandle buffer : {tiles.lights, tiles.ranges, tiles.tiles}) {
      b.read(buffer, rg::Usage::storage_compute);
    }
  };
  if (ranked_) {
    // Named "lighting ...": every "shadow ..." pass counts as shadow work against the time
    // budget (systems/shadow_maps/shadow_pass_times.h).
    graph.add_pass(
        "lighting filter floor",
        [&](rg::PassBuilder& b) {
          read_lighting_inputs(b);
          lit_sum = b.write(lit_sum, rg::Usage::storage_compute);
        },
        [this, bind, lit_sum, constants, grid](const vk::PassRecorder& rec) {
          bind(rec, filter_floor_pipeline_.get(), lit_sum, constants);
          vkCmdDispatch(rec.cmd(), grid.across, grid.down, 1);  // a workgroup a tile
        });
  }
  for (uint32_t group = 0; group < shadows::light_group_count; ++group) {
    if (current_[group] == VK_NULL_HANDLE) continue;  // no light of the group this frame
    graph.add_pass(
        "lighting " + group_name(group),
        [&](rg::PassBuilder& b) {
          read_lighting_inputs(b);
          b.read(tiles.commands, rg::Usage::indirect);
          lit_sum = b.write(lit_sum, rg::Usage::storage_compute);
        },
        [group, bind, tiles, lit_sum, constants = with_group_light(constants, group_light_[group]),
         pipeline = current_[group]](const vk::PassRecorder& rec) {
          bind(rec, pipeline, lit_sum, constants);
          vkCmdDispatchIndirect(rec.cmd(), rec.buffer(tiles.commands),
                                LightTilesPass::dispatch_offset(group));
        });
  }
  for (uint32_t s = 0; s < group_sets_.size(); ++s) {
    if (set_pipelines_[s] == VK_NULL_HANDLE) continue;
    graph.add_pass(
        "lighting " + set_name(group_sets_[s]),
        [&](rg::PassBuilder& b) {
          read_lighting_inputs(b);
          b.read(tiles.commands, rg::Usage::indirect);
          lit_sum = b.write(lit_sum, rg::Usage::storage_compute);
        },
        [s, bind, tiles, lit_sum, constants = with_set(constants, group_sets_[s], s, group_light_),
         pipeline = set_pipelines_[s]](const vk::PassRecorder& rec) {
          bind(rec, pipeline, lit_sum, constants);
          vkCmdDispatchIndirect(rec.cmd(), rec.buffer(tiles.commands),
                                LightTilesPass::dispatch_offset(shadows::light_group_count + s));
        });
  }
  if (probing_) {
    const VkPipeline probe_pipeline = probe_pipelines_[ranked_ ? 1 : 0].get();
    // Reads the lit sum for its filter floor; the probe's buffers live outside the graph
    // (ShadowProbe records their barriers), read once the frame has completed.
    graph.add_pass(
        "lighting shadow probe",
        [&](rg::PassBuilder& b) {
          read_lighting_inputs(b);
          lit_sum = b.write(lit_sum, rg::Usage::storage_compute);
        },
        [bind, lit_sum, constants, probe_pipeline, probe = probe_](const vk::PassRecorder& rec) {
          probe->record_start(rec.cmd());
          bind(rec, probe_pipeline, lit_sum, constants, probe->buffer().handle());
          vkCmdDispatch(rec.cmd(), (constants.screen.x + 15) / 16, (constants.screen.y + 15) / 16, 1);
          probe->record_finish(rec.cmd());
        });
  }
  return lit_sum;
}

}  // namespace sg
