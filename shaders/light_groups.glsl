// SPDX-License-Identifier: MIT
// Lights grouped by the shadow code they run: a group is a shadow kind (none, a 2D map, a cube
// map) and, for shadowed lights, one of the five algorithms. The tiled lighting pass runs one
// dispatch per group with that group's code compiled in and nothing else (a CPU Vulkan driver
// pays for every branch a shader contains, taken or not). Also compiled as C++
// (systems/shadows/light_groups.cpp), so both sides number groups the same way: keep to what both
// languages read alike.
#ifndef SG_LIGHT_GROUPS_GLSL
#define SG_LIGHT_GROUPS_GLSL

const uint SHADOW_KIND_NONE = 0u;
const uint SHADOW_KIND_MAP = 1u;   // spot, directional and cylinder lights: one 2D map
const uint SHADOW_KIND_CUBE = 2u;  // point lights: a cube map

const uint LIGHT_GROUP_COUNT = 11u;  // unshadowed, then 2D x 5 algorithms, then cube x 5

uint light_group(uint shadow_kind, uint algorithm) {
  if (shadow_kind == SHADOW_KIND_NONE) return 0u;
  return (shadow_kind == SHADOW_KIND_MAP ? 1u : 6u) + algorithm;
}

uint group_shadow_kind(uint group) {
  return group == 0u ? SHADOW_KIND_NONE : (group < 6u ? SHADOW_KIND_MAP : SHADOW_KIND_CUBE);
}

uint group_algorithm(uint group) { return group == 0u ? 0u : (group - 1u) % 5u; }

#endif
