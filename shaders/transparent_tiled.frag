// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant groups_1 GROUP_SLOTS=1
// variant groups_2 GROUP_SLOTS=2
// variant groups_3 GROUP_SLOTS=3
// variant groups_4 GROUP_SLOTS=4
// Transparent surfaces lit from tile lists (systems/lighting/transparent_pass.h): ambient plus the lights
// of this pixel's screen tile (light_tiles.comp, its transparent variant), group by group, each
// group's shadow kind and algorithm a constant, and the surface's alpha for blending. Where
// frame.counts.w is 1 the color is tone-mapped with the exposure in counts.z, for a frame that
// is already: the curve is the identity below its knee, where blending after it is blending
// before. GROUPS_PRESENT (a specialization constant, bit g for group g) removes the groups the
// frame has no light of, so the shader holds only the shadow code the frame uses; the groups_N
// variants call the shading for the frame's N groups alone (group_slots.glsl).
#include "group_slots.glsl"
#include "light_shading.glsl"
#include "light_tiles.glsl"
#include "material.glsl"
#include "tone_map.glsl"

layout(constant_id = 0) const uint GROUPS_PRESENT = 0x7FFu;
// constant_id 5: each group's light types (group_light_types), as scene_fused.frag's.
layout(constant_id = 5) const uint GROUP_TYPES = 0x3FFFFFFFu;

layout(std430, set = 0, binding = tile_lights_binding) readonly buffer TileLights { uint tile_lights[]; };
layout(std430, set = 0, binding = tile_ranges_binding) readonly buffer TileRanges { uvec2 tile_ranges[]; };

layout(location = 0) out vec4 out_color;

// The tile's lights of `group`. A CPU driver runs the loop body at least once, masked where
// the tile has none of the group's lights, and a for loop once more than its count: a do-while
// runs it max(count, 1) times. The masked pass reads a valid record (index clamped).
vec3 shade_group(uint group, uint tile, SurfacePoint p) {
  vec3 color = vec3(0.0);
  if ((GROUPS_PRESENT & (1u << group)) == 0u) return color;
  uvec2 range = tile_ranges[tile * LIGHT_GROUP_COUNT + group];
  if (range.y == 0u) return color;
  uint j = 0u;
  do {
    uint light = min(tile_lights[range.x + j], frame.counts.x - 1u);
    color += shade_light_as(light_at(light), p, in_world_position, group_shadow_kind(group), group_algorithm(group),
                            0.0, group_light_types(GROUP_TYPES, group));
    ++j;
  } while (j < range.y);
  return color;
}

void main() {
  SurfacePoint p = fragment_surface();
  uvec2 tile_xy = uvec2(gl_FragCoord.xy) / LIGHT_TILE_SIZE;
  uint tile = tile_xy.y * frame.counts.y + tile_xy.x;  // counts.y: tiles across
  vec3 color = frame.ambient.rgb * p.base_color;
  // A call a group slot (group_slots.glsl), each with a group that is a constant, so that its shadow
  // code is resolved when the pipeline is built.
#define SHADE_SLOT(slot) color += shade_group(slot_group(slot), tile, p);
  FOR_EACH_GROUP_SLOT(SHADE_SLOT)
  if (frame.counts.w == 1u) color = tone_map(color, uintBitsToFloat(frame.counts.z));
  out_color = vec4(color, fragment_base_color().a);
}
