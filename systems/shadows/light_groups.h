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

// Bit g set for each group g with lights, from group_begin as in FrameLights (group g's records
// are [group_begin[g], group_begin[g + 1])): the GROUPS_PRESENT of the forward shaders.
inline uint32_t groups_present(const std::array<uint32_t, light_group_count + 1>& group_begin) {
  uint32_t present = 0;
  for (uint32_t group = 0; group < light_group_count; ++group) {
    if (group_begin[group + 1] > group_begin[group]) present |= 1u << group;
  }
  return present;
}

}  // namespace sg::shadows
