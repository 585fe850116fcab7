// SPDX-License-Identifier: MIT
// Light culling (light_tiles.comp on GPUs, light_tiles_serial.comp on CPU drivers): per screen
// tile of LIGHT_TILE_SIZE pixels, it bounds the tile's visible surfaces (nearest to farthest
// depth, background excluded; TileVolume), lists every light that reaches them in light-index
// order, and, since the records are sorted by light group (systems/shadows/frame_lights.h),
// finds each group's range in that list. A tile's list is as long as its lights: each tile counts
// them first, then takes that many entries of one pool shared by all tiles (take_entries); where
// the pool runs out, a tile lists the lights worth most to it (light_worth_bits). Every tile with
// lights of a group is in that group's tile list, whose length is the group's indirect dispatch
// (tiled_lighting.comp): appended on CPU drivers, in its own slot in tile order on GPUs. Both
// shapes write the same light lists; on GPUs a coarse pass first (light_tiles_coarse.glsl)
// bounds the tiles and narrows the lights each tile tests.
//
// Group sets (CPU drivers' shape only): a tile is listed for the pass of the largest of
// frame.sets among its groups with lights (tiled_lighting.comp shades all the set's groups), and
// for its other groups' own passes, instead of once for each group's: every pass pays for reading
// the G-buffer and the lit sum at its pixels whatever its lights. The CPU picks the sets from the
// tiles an earlier frame counted for each combination of groups (tiles_by_groups).
// Their transparent variants (systems/lighting/transparent_pass.h) bound each tile by where
// transparent surfaces may lie in it too (light_tile_bounds.glsl).
#ifndef SG_LIGHT_TILES_INTERFACE_GLSL
#define SG_LIGHT_TILES_INTERFACE_GLSL

#include "bindings.glsl"
#include "camera_depth.glsl"
#include "light_formulas.glsl"
#include "light_groups.glsl"
#include "light_record.glsl"
#include "light_tiles.glsl"

// The tiles' lists and their dispatches are declared in light_tile_lists.glsl, the coarse pass's
// buffers in light_tiles_coarse.glsl: a CPU driver touches every buffer a shader declares, so each
// shader declares only the buffers its pass binds.
layout(std430, set = 0, binding = lights_binding) readonly buffer Lights { Light lights[]; };
// Zeroed by the CPU before the frame, read back after it (LightTilesPass::take_dropped_pairs).
layout(std430, set = 0, binding = light_tiles_feedback_binding) buffer Feedback {
  uint dropped_pairs;   // (tile, light) pairs that reached a tile but found no room in the pool
  uint entries_wanted;  // the entries every tile's lights asked of the pool: what sizes it
  uint coarse_wanted;   // the same of the coarse tiles' pool (light_tiles_coarse.glsl)
  uint tiles_cut;       // tiles whose lists a CPU driver's loop guard cut short (light_tiles_serial.comp)
  // Per combination of two groups or more (bit g for group g), the tiles whose groups with lights
  // it is (CPU drivers' shape only).
  uint tiles_by_groups[1u << LIGHT_GROUP_COUNT];
};

layout(push_constant) uniform Constants {
  mat4 inverse_view_projection;
  uvec4 screen;  // x width, y height, z tiles across, w tiles in all
  uvec4 counts;  // x lights, y entries in the pool (tile_lights), z entries in the coarse pool,
                 // w the coarse pass's workgroups per coarse tile (LIGHT_COARSE_SEGMENTS at most)
  uvec4 sets[LIGHT_GROUP_SETS / 4u];  // the group sets, bit g for group g; 0: none
} frame;

uint group_of(uint light) {
  Light l = lights[light];
  uint kind = l.info.w == NO_SHADOW_MAP ? SHADOW_KIND_NONE
                                        : (l.info.x == LIGHT_POINT ? SHADOW_KIND_CUBE : SHADOW_KIND_MAP);
  return light_group(kind, light_algorithm(l));
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

// Whether light `i` goes in the list of `tile`: it reaches the tile and is worth at least `least`
// there (0: every light that reaches it).
bool listed_in_tile(uint i, TileVolume tile, uint least) {
  return light_reaches_tile(lights[i], tile) && (least == 0u || light_worth_bits(lights[i], tile.sphere) >= least);
}

#endif
