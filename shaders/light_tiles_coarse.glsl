// SPDX-License-Identifier: MIT
// The coarse pass of light culling on GPUs (light_tiles_coarse.comp) and what the tiles' pass
// (light_tiles.comp) reads from it. Testing every light in every tile costs lights times tiles,
// each test reading a light record: 100,000 lights over 1920x1080's 8,160 tiles took 8.5 ms (the
// stress hall from afar) to 54-85 ms (at eye height) on the H200 (2026-12-03). The coarse pass
// bounds each tile's surfaces (TileVolume), once; then each coarse tile (LIGHT_COARSE_SIDE tiles a
// side) lists, in light order, the lights that reach a volume around its tiles' volumes, and a tile
// tests only that list. The list holds every light that reaches any of its tiles: the tests of
// light_reaches_volume only grow with the sphere, the cone and the shells, and light_reaches_sphere's
// move no faster than the sphere's centre; the tiles' own depth slices and spot tests come after.
#ifndef SG_LIGHT_TILES_COARSE_GLSL
#define SG_LIGHT_TILES_COARSE_GLSL

#include "light_tiles_interface.glsl"

// Per tile, the volume of its visible surfaces (visible_volume_of_tile); sphere.w < 0 where it has
// none.
layout(std430, set = 0, binding = tile_volumes_binding) buffer TileVolumes { TileVolume tile_volumes[]; };
// The pool of the coarse tiles' lists, frame.counts.z entries.
layout(std430, set = 0, binding = coarse_lights_binding) buffer CoarseLights { uint coarse_lights[]; };
// Per coarse tile, per segment of the lights (LIGHT_COARSE_SEGMENTS, in light order): x its list's
// first entry in coarse_lights, y how many, or EVERY_LIGHT where the pool had no room for its list
// (its tiles then test every light; the pool grows for the frames after).
layout(std430, set = 0, binding = coarse_ranges_binding) buffer CoarseRanges { uvec2 coarse_ranges[]; };

const uint EVERY_LIGHT = 0xFFFFFFFFu;
const float NO_SURFACES = -1.0;

// A coarse list's entry: the light's index in the low bits, and above them a bit per quadrant of
// the coarse tile (LIGHT_COARSE_SIDE / 2 tiles a side) whose volume the light reaches, so that a
// tile tests only its quadrant's lights. Among 100,000 lights the tiles' pass took 0.75 ms against
// 1.41 from afar and 1.59 against 2.01 at eye height, the coarse pass 0.63 against 0.43 and 0.85
// against 0.70: the frame 12.0 ms against 12.45, and 25.05 against 25.3. Coarse tiles of 4 x 4
// tiles instead cost the coarse pass 2.29 ms at eye height (H100, 1920x1080, 2026-12-05).
const uint COARSE_QUADRANT_SHIFT = 28u;
const uint COARSE_ENTRY_LIGHT = (1u << COARSE_QUADRANT_SHIFT) - 1u;  // the light's index

// The quadrant (0 to 3) of the coarse tile that the tile at `in_coarse` (its place in its coarse
// tile) lies in.
uint coarse_quadrant(uvec2 in_coarse) {
  uvec2 half_side = in_coarse / (LIGHT_COARSE_SIDE / 2u);
  return half_side.y * 2u + half_side.x;
}

// The first of the LIGHT_COARSE_SEGMENTS ranges in coarse_ranges of the coarse tile holding the
// tile at `tile_xy`.
uint first_coarse_range(uvec2 tile_xy) {
  uint across = (frame.screen.z + LIGHT_COARSE_SIDE - 1u) / LIGHT_COARSE_SIDE;
  uvec2 coarse = tile_xy / LIGHT_COARSE_SIDE;
  return (coarse.y * across + coarse.x) * LIGHT_COARSE_SEGMENTS;
}

#endif
