// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant storage_records LIGHT_RECORDS_IN_STORAGE
// variant warp_lists LIGHT_RECORDS_IN_STORAGE WARP_LISTS
// Tiled deferred lighting of one light group in compute (tiled_lighting.glsl): one workgroup per
// slot of the group's dispatch list (the culling's; an indirect dispatch), which names a tile that
// has lights of the group or NO_TILE, each invocation one pixel, adding the group's lights to the
// lit sum. With RANKED_FILTERING the lit sum's alpha holds the pixel's filter floor
// (lighting_filter_floor.comp).
#include "tiled_lighting.glsl"
#ifdef WARP_LISTS
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_shuffle : require
#endif

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = hdr_binding, rgba16f) uniform image2D hdr;
layout(std430, set = 0, binding = group_tiles_binding) readonly buffer GroupTiles { uint group_tiles[]; };

// Where the records come from a storage buffer (GPUs), the unshadowed group's lights are loaded
// into shared memory a batch at a time (light_batch.glsl): their shading is short, and each
// light's load stood between a pixel and it (H200, 1920x1080, 100,000 lights: the pass took 4.0
// ms against 8.0 at eye height, 1.8 against 3.0 from afar, 2026-12-03). Shadowed groups read
// their records directly: with a batch of whole records their passes took 40-190% longer, and so
// did every pass declaring one, shared memory taken from the cache their shadow-map taps use. So
// other pipelines hold a batch of one. A CPU driver takes the texel-buffer variant, which has no
// barriers to pay.
#ifdef LIGHT_RECORDS_IN_STORAGE
const bool BATCHED = LIGHT_GROUP == 0u && !SINGLE_LIGHT;
#else
const bool BATCHED = false;
#endif
const uint LIGHT_BATCH = BATCHED ? 256u : 1u;  // one light an invocation
#include "light_batch.glsl"

// The unshadowed lights of `tile` at the surface point, where `surface`; every invocation of the
// workgroup calls it, for the batches' barriers.
vec3 shade_tile_batched(uint tile, bool surface, SurfacePoint p, vec3 position, float filter_floor) {
  uvec2 range = tile_ranges[tile * LIGHT_GROUP_COUNT + LIGHT_GROUP];
  vec3 color = vec3(0.0);
  for (uint first = 0u; first < range.y; first += LIGHT_BATCH) {
    uint count = min(range.y - first, LIGHT_BATCH);
    if (gl_LocalInvocationIndex < count) {
      keep_in_batch(gl_LocalInvocationIndex, light_at(tile_lights[range.x + first + gl_LocalInvocationIndex]));
    }
    barrier();
    for (uint j = 0u; surface && j < count; ++j) {
      color += shade_light_as(batch_light(j), p, position, SHADOW_KIND_NONE, SHADOW_HARD, filter_floor, LIGHT_TYPES);
    }
    barrier();
  }
  return color;
}

#ifdef WARP_LISTS
// The warp_lists variant (GPUs whose subgroups, 32 lanes at most, ballot, shuffle and reduce in
// compute): a cube group's lights are culled again for each warp's 8x4 pixels. Of each chunk of
// the tile's list, a light a lane, only those whose range reaches the box around the warp's
// surface points are shaded, in the list's order (the same sum), the warp looping over them
// together: a tile's list holds every light that reaches its depth slices, and from afar many
// miss a warp's pixels. An H100 took 10.80-10.82 ms a frame against 11.21-11.22 from afar and
// 22.08-22.11 against 22.47 at eye height (1920x1080, 100,000 lights, 2026-12-06). The cube groups
// alone take it: with every group culled so, the 2D groups' passes gained nothing, a spot's cone,
// bounded by a sphere, rejecting too few to pay for its test. A short list is looped as it is.
vec3 shade_tile_group_by_warp(uint tile, SurfacePoint p, vec3 position, float filter_floor) {
  uvec2 range = tile_ranges[tile * LIGHT_GROUP_COUNT + LIGHT_GROUP];
  if (range.y < 32u) return shade_tile_group(tile, p, position, filter_floor);
  vec3 low = subgroupMin(position);
  vec3 high = subgroupMax(position);
  uvec4 lanes_in = subgroupBallot(true);
  uint lanes = subgroupBallotBitCount(lanes_in);
  uint rank = subgroupBallotExclusiveBitCount(lanes_in);
  vec3 color = vec3(0.0);
  for (uint first = 0u; first < range.y; first += lanes) {
    bool listed = first + rank < range.y;
    uint index = listed ? tile_lights[range.x + first + rank] : 0u;
    vec4 position_range = light_records[index].position_range;
    vec3 offset = position_range.xyz - clamp(position_range.xyz, low, high);
    uint reaching = subgroupBallot(listed && dot(offset, offset) <= position_range.w * position_range.w).x;
    while (reaching != 0u) {
      uint lane = findLSB(reaching);
      reaching &= reaching - 1u;
      color += shade_light_as(light_at(subgroupShuffle(index, lane)), p, position, SHADOW_KIND_CUBE,
                              group_algorithm(LIGHT_GROUP), filter_floor, LIGHT_TYPES);
    }
  }
  return color;
}
#endif

void main() {
  uint tile = group_tiles[LIGHT_GROUP * frame.screen.w + gl_WorkGroupID.x];
  if (tile == NO_TILE) return;
  uvec2 tile_xy = uvec2(tile % frame.screen.z, tile / frame.screen.z);
  ivec2 pixel = ivec2(tile_xy * LIGHT_TILE_SIZE + pixel_in_tile());
  SurfacePoint p;
  vec3 position;
  bool surface = pixel.x < int(frame.screen.x) && pixel.y < int(frame.screen.y) &&
                 deferred_surface(pixel, p, position);
  if (!surface && !BATCHED) return;  // a batched pass keeps every invocation for its barriers
  begin_contact_shadows(pixel);
  vec4 sum = surface ? imageLoad(hdr, pixel) : vec4(0.0);
  float filter_floor = RANKED_FILTERING ? sum.a : 0.0;
#ifdef WARP_LISTS
  bool by_warp = !SINGLE_LIGHT && group_shadow_kind(LIGHT_GROUP) == SHADOW_KIND_CUBE;
  vec3 color = BATCHED   ? shade_tile_batched(tile, surface, p, position, filter_floor)
               : by_warp ? shade_tile_group_by_warp(tile, p, position, filter_floor)
                         : shade_tile_group(tile, p, position, filter_floor);
#elif defined(LIGHT_RECORDS_IN_STORAGE)
  vec3 color = BATCHED ? shade_tile_batched(tile, surface, p, position, filter_floor)
                       : shade_tile_group(tile, p, position, filter_floor);
#else
  vec3 color = shade_tile_group(tile, p, position, filter_floor);  // one call of the shading
#endif
  if (surface) imageStore(hdr, pixel, sum + vec4(color, 0.0));
}
