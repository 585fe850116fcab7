// SPDX-License-Identifier: MIT
#pragma once
// Lights grouped by the shadow code they run: none, a 2D map or a cube map, and for shadowed
// lights their algorithm. The numbering is shaders/light_groups.glsl's, compiled here as C++, so
// the CPU that sorts lights by group and the shaders that run one group agree.
#include <array>
#include <cstdint>

#include "systems/scene/shadow_settings.h"

namespace sg::shadows {

inline constexpr uint32_t light_group_count = 11;

enum class ShadowKind : uint32_t { none = 0, map = 1, cube = 2 };

uint32_t light_group(ShadowKind kind, scene::ShadowAlgorithm algorithm);
ShadowKind group_shadow_kind(uint32_t group);
scene::ShadowAlgorithm group_algorithm(uint32_t group);

// What a shader that shades every light group of a frame in one pass is specialized on
// (shaders/scene_fused.frag): the groups with lights (bit g for group g), those with exactly one,
// the light types among them all (light_type_bits, gpu_light.h) and each group's, so that a group
// holds the code of its own lights' types alone. A CPU driver runs every branch a shader holds,
// so each is code left out.
struct GroupsPresent {
  uint32_t present = 0;
  uint32_t single = 0;
  uint32_t light_types = 0;
  // Five bits a group for the unshadowed and the 2D groups (lights_interface.glsl's
  // group_light_types); a cube group's lights are point lights.
  uint32_t group_types = 0;

  // key_bits bits: the others follow from these.
  static constexpr uint32_t key_bits = 2 * light_group_count + 30;
  uint64_t key() const {
    return present | uint64_t{single} << light_group_count | uint64_t{group_types} << 2 * light_group_count;
  }
};

// Groups whose light types GroupsPresent::group_types holds: the unshadowed and the 2D ones.
inline constexpr uint32_t groups_with_own_types = 6;

// The light types of groups `groups` (bit g for group g), each group's `group_types[g]`, packed
// as GroupsPresent::group_types.
inline uint32_t packed_group_types(uint32_t groups,
                                   const std::array<uint32_t, light_group_count>& group_types) {
  uint32_t packed = 0;
  for (uint32_t group = 0; group < groups_with_own_types; ++group) {
    if ((groups >> group & 1u) != 0) packed |= group_types[group] << 5 * group;
  }
  return packed;
}

// Groups `groups` (bit g for group g) in order, four bits each, the first eight, the slots past
// the last holding 15: the group slots of shaders/group_slots.glsl.
inline uint32_t group_slot_list(uint32_t groups) {
  uint32_t list = 0xFFFFFFFFu;
  uint32_t slot = 0;
  for (uint32_t group = 0; group < light_group_count && slot < 8; ++group) {
    if ((groups >> group & 1u) != 0) {
      list &= ~(0xFu << 4 * slot);
      list |= group << 4 * slot++;
    }
  }
  return list;
}

// From group_begin and group_types as in FrameLights (group g's records are [group_begin[g],
// group_begin[g + 1]), their types group_types[g]).
inline GroupsPresent groups_present(const std::array<uint32_t, light_group_count + 1>& group_begin,
                                    const std::array<uint32_t, light_group_count>& group_types) {
  GroupsPresent groups;
  for (uint32_t group = 0; group < light_group_count; ++group) {
    const uint32_t lights = group_begin[group + 1] - group_begin[group];
    if (lights > 0) groups.present |= 1u << group;
    if (lights == 1) groups.single |= 1u << group;
    groups.light_types |= group_types[group];
  }
  groups.group_types = packed_group_types(groups.present, group_types);
  return groups;
}

}  // namespace sg::shadows
