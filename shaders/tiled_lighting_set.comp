// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant storage_records LIGHT_RECORDS_IN_STORAGE
// Tiled deferred lighting of a group set (light_tiles_interface.glsl): one workgroup per tile the
// culling listed for the set, each invocation one pixel, adding the lights of the set's groups
// to the lit sum in one pass, each group with its own algorithm's and light types' code: a call
// of the shading for each of the set's groups (group_slots.glsl), at most four.
#define GROUP_SLOTS 4  // LIGHT_GROUPS_A_SET
#include "group_slots.glsl"
#include "tiled_lighting.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = hdr_binding, rgba16f) uniform image2D hdr;
layout(std430, set = 0, binding = group_tiles_binding) readonly buffer GroupTiles { uint group_tiles[]; };

// constant_id 8 (0 to 5 and 7 are tiled_lighting.glsl's and what it includes, 6 group_slots.glsl's:
// the set's groups, each with a single light, their lights in frame.lights in group order): their
// light types, five bits a group (group_light_types).
layout(constant_id = 8) const uint SET_GROUP_TYPES = 0u;

// The light of the set's group in slot `slot` (group_slots.glsl) at the surface point: the
// slot-th of frame.lights. A slot the set leaves empty holds no group.
vec3 shade_set_slot(uint slot, SurfacePoint p, vec3 position, float filter_floor) {
  uint group = slot_group(slot);
  if (group >= LIGHT_GROUP_COUNT) return vec3(0.0);
  return shade_light_as(light_at(frame.lights[slot]), p, position, group_shadow_kind(group), group_algorithm(group),
                        filter_floor, group_light_types(SET_GROUP_TYPES, group));
}

// A group set's lights at the surface point: one pass for the tile's groups, which pays for the
// G-buffer and the lit sum once. Each group keeps its own algorithm's and light types' code.
vec3 shade_tile_set(SurfacePoint p, vec3 position, float filter_floor) {
  vec3 color = vec3(0.0);
#define SHADE_SLOT(slot) color += shade_set_slot(slot, p, position, filter_floor);
  FOR_EACH_GROUP_SLOT(SHADE_SLOT)
  return color;
}

void main() {
  // Group sets' tile lists follow the groups' (light_tile_lists.glsl).
  uint tile = group_tiles[(LIGHT_GROUP_COUNT + frame.set.x) * frame.screen.w + gl_WorkGroupID.x];
  uvec2 tile_xy = uvec2(tile % frame.screen.z, tile / frame.screen.z);
  ivec2 pixel = ivec2(tile_xy * LIGHT_TILE_SIZE + pixel_in_tile());
  SurfacePoint p;
  vec3 position;
  if (pixel.x >= int(frame.screen.x) || pixel.y >= int(frame.screen.y) || !deferred_surface(pixel, p, position)) {
    return;
  }
  begin_contact_shadows(pixel);
  vec4 sum = imageLoad(hdr, pixel);
  float filter_floor = RANKED_FILTERING ? sum.a : 0.0;
  imageStore(hdr, pixel, sum + vec4(shade_tile_set(p, position, filter_floor), 0.0));
}
