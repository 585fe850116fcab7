// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant storage_records LIGHT_RECORDS_IN_STORAGE
// Tiled deferred lighting of a group set (light_tiles_interface.glsl): one workgroup per tile the
// culling listed for the set, each invocation one pixel, adding the lights of the set's groups
// to the lit sum in one pass, each group with its own algorithm's and light types' code. A shader
// of its own: the compiler inlines every group's shading before it drops the groups a pipeline
// lacks, and in tiled_lighting.comp those eleven calls slowed every group pipeline's build.
#include "tiled_lighting.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = hdr_binding, rgba16f) uniform image2D hdr;
layout(std430, set = 0, binding = group_tiles_binding) readonly buffer GroupTiles { uint group_tiles[]; };

// constant_id 8 (0 to 7 are tiled_lighting.glsl's and what it includes): the set's groups, bit g
// for group g, each with a single light, the lights in frame.lights in group order. 9: their light
// types, five bits a group (group_light_types).
layout(constant_id = 8) const uint GROUP_SET = 0u;
layout(constant_id = 9) const uint SET_GROUP_TYPES = 0u;

// Group `group`'s light at the surface point, where it is in the set: the k-th of frame.lights,
// k counting the set's groups so far. Called with literal groups, so that the rest folds away.
vec3 shade_set_group(uint group, inout uint k, SurfacePoint p, vec3 position, float filter_floor) {
  if ((GROUP_SET & (1u << group)) == 0u) return vec3(0.0);
  uint light = frame.lights[k++];
  return shade_light_as(light_at(light), p, position, group_shadow_kind(group), group_algorithm(group),
                        filter_floor, group_light_types(SET_GROUP_TYPES, group));
}

// A group set's lights at the surface point: one pass for the tile's groups, which pays for the
// G-buffer and the lit sum once. Each group keeps its own algorithm's and light types' code.
vec3 shade_tile_set(SurfacePoint p, vec3 position, float filter_floor) {
  uint k = 0u;
  vec3 color = shade_set_group(0u, k, p, position, filter_floor);
  color += shade_set_group(1u, k, p, position, filter_floor);
  color += shade_set_group(2u, k, p, position, filter_floor);
  color += shade_set_group(3u, k, p, position, filter_floor);
  color += shade_set_group(4u, k, p, position, filter_floor);
  color += shade_set_group(5u, k, p, position, filter_floor);
  color += shade_set_group(6u, k, p, position, filter_floor);
  color += shade_set_group(7u, k, p, position, filter_floor);
  color += shade_set_group(8u, k, p, position, filter_floor);
  color += shade_set_group(9u, k, p, position, filter_floor);
  color += shade_set_group(10u, k, p, position, filter_floor);
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
