// SPDX-License-Identifier: MIT
// Where a tile's visible surfaces lie, for the culling shaders that read the scene's depth
// (light_tiles_serial.comp, light_tiles_coarse.comp): its depth bounds and the volume they bound.
#ifndef SG_LIGHT_TILE_BOUNDS_GLSL
#define SG_LIGHT_TILE_BOUNDS_GLSL

#include "light_tiles_interface.glsl"

layout(set = 0, binding = scene_depth_binding) uniform sampler2D scene_depth;
#ifdef TRANSPARENT_BOUNDS
// Per tile, where transparent surfaces may lie (systems/lighting/transparent_tile_bounds.h): x the nearest
// depth, y the farthest; x is 0 where there are none.
layout(std430, set = 0, binding = transparent_bounds_binding) readonly buffer TransparentBounds {
  vec2 transparent_bounds[];
};
#endif

// Widens a tile's depth bounds, [farthest, nearest] in reversed depths (camera_depth.glsl: the
// nearest surface has the greatest), by a pixel's `depth`; background bounds nothing.
void bound_by_depth(float depth, inout float nearest, inout float farthest) {
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

// The volume of tile `tile_xy`'s visible surfaces, between depths `nearest` and `farthest`.
TileVolume visible_volume_of_tile(uvec2 tile_xy, float nearest, float farthest) {
  vec2 texel = 2.0 / vec2(frame.screen.xy);
  vec2 ndc_min = vec2(tile_xy * LIGHT_TILE_SIZE) * texel - 1.0;
  vec2 ndc_max = min(vec2((tile_xy + 1u) * LIGHT_TILE_SIZE) * texel - 1.0, vec2(1.0));
  return tile_volume(frame.inverse_view_projection, ndc_min, ndc_max, nearest, farthest);
}

// The depth slice of `tile` (depth_slice_bit) that holds a surface at `depth`; none for the
// background.
uint depth_slice_of(TileVolume tile, float depth) {
  return is_background_depth(depth) ? 0u : depth_slice_bit(depth_slice_position(tile, depth));
}

// In the transparent variants, the depth slices of tile `tile_index` (`tile`) from the nearest to
// the farthest depth where transparent surfaces may lie; none otherwise.
uint depth_slices_of_transparent_surfaces(uint tile_index, TileVolume tile) {
#ifdef TRANSPARENT_BOUNDS
  vec2 bounds = transparent_bounds[tile_index];
  if (bounds.x > 0.0) {
    return depth_slices_between(depth_slice_of(tile, bounds.x), depth_slice_of(tile, bounds.y));
  }
#endif
  return 0u;
}
#endif
