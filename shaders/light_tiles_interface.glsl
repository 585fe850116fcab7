// SPDX-License-Identifier: MIT
// Light culling (light_tiles.comp on GPUs, light_tiles_serial.comp on CPU drivers): per screen
// tile of LIGHT_TILE_SIZE pixels, it bounds the tile's visible surfaces (nearest to farthest
// depth, background excluded) by a sphere, lists every light that reaches it in light-index
// order, and, since the records are sorted by light group (systems/shadows/frame_lights.h),
// finds each group's range in that list. A tile's list is as long as its lights: each tile counts
// them first, then takes that many entries of one pool shared by all tiles (take_entries); where the
// pool runs out, a tile lists the lights worth most to it (light_worth_bits). Every tile with lights of a group is appended to that
// group's tile list, whose length is the group's indirect dispatch (tiled_lighting.comp). Both
// shaders write the same lists.
// Their transparent variants (systems/lighting/transparent_pass.h) bound each tile by where transparent
// surfaces may lie in it too.
#ifndef SG_LIGHT_TILES_INTERFACE_GLSL
#define SG_LIGHT_TILES_INTERFACE_GLSL

#include "bindings.glsl"
#include "camera_depth.glsl"
#include "light_formulas.glsl"
#include "light_groups.glsl"
#include "light_record.glsl"
#include "light_tiles.glsl"

layout(std430, set = 0, binding = lights_binding) readonly buffer Lights { Light lights[]; };
layout(set = 0, binding = scene_depth_binding) uniform sampler2D scene_depth;
#ifdef TRANSPARENT_BOUNDS
// Per tile, where transparent surfaces may lie (systems/lighting/transparent_tile_bounds.h): x the nearest
// depth, y the farthest; x is 0 where there are none.
layout(std430, set = 0, binding = transparent_bounds_binding) readonly buffer TransparentBounds {
  vec2 transparent_bounds[];
};
#endif
// The pool of every tile's list, frame.counts.y entries.
layout(std430, set = 0, binding = tile_lights_binding) writeonly buffer TileLights { uint tile_lights[]; };
// Per tile and group: x the first entry in tile_lights, y how many.
layout(std430, set = 0, binding = tile_ranges_binding) writeonly buffer TileRanges { uvec2 tile_ranges[]; };
// Per group, tile_count slots: the tiles that have lights of the group, in no particular order.
layout(std430, set = 0, binding = group_tiles_binding) writeonly buffer GroupTiles { uint group_tiles[]; };
// Per group a VkDispatchIndirectCommand (x counts the group's tiles; y = z = 1), at a 16-byte
// stride.
layout(std430, set = 0, binding = group_commands_binding) buffer GroupCommands { uvec4 group_commands[]; };
// Zeroed by the CPU before the frame, read back after it (LightTilesPass::take_dropped_pairs).
layout(std430, set = 0, binding = light_tiles_feedback_binding) buffer Feedback {
  uint dropped_pairs;   // (tile, light) pairs that reached a tile but found no room in the pool
  uint entries_wanted;  // the entries every tile's lights asked of the pool: what sizes it
};

layout(push_constant) uniform Constants {
  mat4 inverse_view_projection;
  uvec4 screen;  // x width, y height, z tiles across, w tiles in all
  uvec4 counts;  // x lights, y entries in the pool (tile_lights)
} frame;

// Takes `wanted` entries of the pool for one tile's list: returns the first, and in `listed` how
// many of them the pool holds (all of them unless it ran out this frame; the rest are counted as
// dropped, and the CPU grows the pool for the frames after).
uint take_entries(uint wanted, out uint listed) {
  listed = 0u;
  if (wanted == 0u) return 0u;
  uint first = atomicAdd(entries_wanted, wanted);
  listed = first >= frame.counts.y ? 0u : min(wanted, frame.counts.y - first);
  if (listed < wanted) atomicAdd(dropped_pairs, wanted - listed);
  return first;
}

uint group_of(uint light) {
  Light l = lights[light];
  uint kind = l.info.w == NO_SHADOW_MAP ? SHADOW_KIND_NONE
                                        : (l.info.x == LIGHT_POINT ? SHADOW_KIND_CUBE : SHADOW_KIND_MAP);
  return light_group(kind, light_algorithm(l));
}

// Widens a tile's depth bounds, [farthest, nearest] in reversed depths (camera_depth.glsl: the
// nearest surface has the greatest), by the surfaces at `pixel`; background bounds nothing.
void bound_by_pixel(ivec2 pixel, inout float nearest, inout float farthest) {
  float depth = texelFetch(scene_depth, pixel, 0).r;
  if (!is_background_depth(depth)) {
    nearest = max(nearest, depth);
    farthest = min(farthest, depth);
  }
}

// Widens a tile's depth bounds by where transparent surfaces may lie in it, in the transparent
// variants; nothing otherwise.
void bound_by_transparent_surfaces(uint tile, inout float nearest, inout float farthest) {
#ifdef TRANSPARENT_BOUNDS
  vec2 bounds = transparent_bounds[tile];
  if (bounds.x > 0.0) {
    nearest = max(nearest, bounds.x);
    farthest = min(farthest, bounds.y);
  }
#endif
}

// The sphere around tile `tile_xy`'s visible surfaces, between depths `nearest` and `farthest`.
vec4 visible_sphere_of_tile(uvec2 tile_xy, float nearest, float farthest) {
  vec2 texel = 2.0 / vec2(frame.screen.xy);
  vec2 ndc_min = vec2(tile_xy * LIGHT_TILE_SIZE) * texel - 1.0;
  vec2 ndc_max = min(vec2((tile_xy + 1u) * LIGHT_TILE_SIZE) * texel - 1.0, vec2(1.0));
  return tile_bounding_sphere(frame.inverse_view_projection, ndc_min, ndc_max, nearest, farthest);
}

// What a light is worth to a tile whose list the pool cannot hold whole: its radiance's luminance
// times its falloff at the nearest point of the tile's sphere (1 for directional and cylinder
// lights), as the bits of that non-negative float, which order as the values do. The lights a
// full pool leaves out of a tile are the least worth there.
uint light_worth_bits(Light light, vec4 sphere) {
  float power = luminance(light.color_intensity.rgb) * light.color_intensity.a;
  float falloff = 1.0;
  if (light.info.x == LIGHT_POINT || light.info.x == LIGHT_SPOT) {
    float distance = max(length(sphere.xyz - light.position_range.xyz) - sphere.w, 0.0);
    float range = light.position_range.w;
    falloff = light_falloff(light) == FALLOFF_GLTF_PUNCTUAL ? falloff_gltf_punctual(distance, range)
                                                    : falloff_linear_window(distance, range);
  }
  return floatBitsToUint(max(power * falloff, 0.0));
}

// Above every light_worth_bits: no light is worth this much.
const uint NO_WORTH = 0x7F800001u;

// Whether light `i` goes in the list of the tile bounded by `sphere`: it reaches the tile and is
// worth at least `least` there (0: every light that reaches it).
bool listed_in_tile(uint i, vec4 sphere, uint least) {
  return light_reaches_sphere(lights[i], sphere) && (least == 0u || light_worth_bits(lights[i], sphere) >= least);
}

// How many of lights [first, end) listed_in_tile lists at worth `least`.
uint count_listed(uint first, uint end, vec4 sphere, uint least) {
  uint count = 0u;
  for (uint i = first; i < end; ++i) {
    if (listed_in_tile(i, sphere, least)) ++count;
  }
  return count;
}

// Records that `tile`'s lights of `group` are the `count` entries of the pool from `first` on,
// and, when there are any, lists the tile for the group's dispatch.
void publish_group_range(uint tile, uint group, uint first, uint count) {
  tile_ranges[tile * LIGHT_GROUP_COUNT + group] = uvec2(first, count);
  if (count == 0u) return;
  uint k = atomicAdd(group_commands[group].x, 1u);
  group_tiles[group * frame.screen.w + k] = tile;
}

#endif
