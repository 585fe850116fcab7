// SPDX-License-Identifier: MIT
// The sizes of tiled light culling, declared once for the shaders (light_tiles.glsl) and the C++
// that allocates their buffers (systems/lighting/light_tiles_pass.h includes this file).
#ifndef SG_LIGHT_TILE_LAYOUT_GLSL
#define SG_LIGHT_TILE_LAYOUT_GLSL

const uint LIGHT_TILE_SIZE = 16u;  // pixels per tile side; one workgroup per tile
// Tiles per coarse tile side (light_tiles_coarse.comp): a coarse tile lists the lights that reach
// any of its tiles, so that each tile tests those only.
const uint LIGHT_COARSE_SIDE = 8u;
// The most workgroups per coarse tile (light_tiles_coarse.comp), each listing a segment of the
// lights; a frame takes that many from LIGHT_COARSE_SEGMENT_LIGHTS lights on, one below.
const uint LIGHT_COARSE_SEGMENTS = 2u;
const uint LIGHT_COARSE_SEGMENT_LIGHTS = 32768u;
// The most group sets a frame shades (light_tiles_interface.glsl): tiles whose light groups are
// one of them take one pass for all those groups.
const uint LIGHT_GROUP_SETS = 8u;
// A slot of a group's dispatch list that names no tile: on GPUs a group's list is in tile order,
// a slot per tile up to the last with the group's lights (light_tile_lists.glsl).
const uint NO_TILE = 0xFFFFFFFFu;
// Light culling on CPU devices (light_tiles_serial.comp) finds a tile's depth slices from this
// many lights on; fewer are listed with every slice counted as holding a surface. With few lights
// the slices drop next to no (tile, light) pairs, and finding them takes a second walk over the
// tile's depths (lavapipe, 1280x720, 2026-12-06: the pass took 1.33-1.43 ms against 1.82-2.04 on
// spot-columns, the same 1,824 pairs; 1.81-2.32 against 2.34-3.16 on default, 8,023 pairs
// against 8,020; pictures bit-identical).
const uint FEWEST_LIGHTS_SLICED = 9u;
// The light groups a group set holds at most (tiled_lighting.glsl: their lights come as push constants).
const uint LIGHT_GROUPS_A_SET = 4u;

#endif
