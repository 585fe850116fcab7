// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant transparent TRANSPARENT_BOUNDS
// Light culling on CPU drivers (light_tiles_interface.glsl says what it writes): one invocation
// per tile, eight tiles a workgroup, no shared memory and no barriers. A CPU driver runs a
// workgroup's invocations as the lanes of SIMD batches and switches between batches at every
// barrier, which was most of light_tiles.comp's cost there; here each lane walks its own tile's
// depths and then the lights in order, which also gives the list its order for free.
#include "light_tile_bounds.glsl"
#include "light_tile_lists.glsl"

layout(local_size_x = 8) in;

// llvmpipe ends every loop of a shader invocation once its loops have run 65,535 iterations in
// all (a guard against endless loops), and an invocation here tests every light twice, each test
// about two iterations (a CPU driver runs a loop's body at least once, masked: the spot test's
// loop over depth slices runs in every test). From about 16,200 of the frame's lights on, a
// tile's loops end before its last lights (lavapipe, Debian 12, 2026-12-05): its lists miss them,
// and the tile counts in tiles_cut, which the CPU reports and --stats counts. Testing sixteen
// lights an iteration, unrolled, ended them sooner (about 14,800).
bool loops_ended_early = false;

// How many of the frame's lights listed_in_tile lists at worth `least`.
uint count_listed(TileVolume tile, uint least) {
  uint count = 0u;
  uint i = 0u;
  for (; i < frame.counts.x; ++i) {
    if (listed_in_tile(i, tile, least)) ++count;
  }
  loops_ended_early = loops_ended_early || i < frame.counts.x;
  return count;
}

// The depths of the 2x2 texels at (x, y) of the tile at `origin`, `texel` a texel's size in uv: one
// gather, which costs a CPU driver what one fetch does. Read twice, for the bounds and then for
// the depth slices, they cost the pass less than a fetch a texel did once, kept in an array:
// 2.23-2.26 ms against 2.93-3.00 (`default`, 1280x720, lavapipe, 2026-12-05). frame.screen is the
// depth image's size and its sampler clamps to the edge, so a block past the screen's edge repeats
// the tile's own texels.
vec4 tile_depths(ivec2 origin, int x, int y, vec2 texel) {
  return textureGather(scene_depth, vec2(origin + ivec2(x + 1, y + 1)) * texel, 0);  // the block's inner corner
}

void main() {
  uint tile = gl_GlobalInvocationID.x;
  if (tile >= frame.screen.w) return;
  uvec2 tile_xy = uvec2(tile % frame.screen.z, tile / frame.screen.z);
  ivec2 origin = ivec2(tile_xy * LIGHT_TILE_SIZE);
  // Reversed depths (camera_depth.glsl): the nearest surface has the greatest.
  float nearest = CAMERA_FAR_DEPTH;
  float farthest = 1.0;
  vec2 texel = 1.0 / vec2(frame.screen.xy);
  for (int y = 0; y < int(LIGHT_TILE_SIZE); y += 2) {
    for (int x = 0; x < int(LIGHT_TILE_SIZE); x += 2) {
      vec4 four = tile_depths(origin, x, y, texel);
      bound_by_depth(four.x, nearest, farthest);
      bound_by_depth(four.y, nearest, farthest);
      bound_by_depth(four.z, nearest, farthest);
      bound_by_depth(four.w, nearest, farthest);
    }
  }
  bound_by_transparent_surfaces(tile, nearest, farthest);

  uint group_first[LIGHT_GROUP_COUNT];
  uint group_count[LIGHT_GROUP_COUNT];
  for (uint g = 0u; g < LIGHT_GROUP_COUNT; ++g) {
    group_first[g] = 0u;
    group_count[g] = 0u;
  }
  // Counts the tile's lights, takes that many entries of the pool, then lists them: testing every
  // light twice costs less than any list of unbounded length kept in between.
  bool surfaces = !is_background_depth(nearest);
  TileVolume volume;
  if (surfaces) {
    volume = visible_volume_of_tile(tile_xy, nearest, farthest);
    uint slices = depth_slices_of_transparent_surfaces(tile, volume);
    // Frames of few lights find no slices (FEWEST_LIGHTS_SLICED), by a loop of no rows: a CPU
    // driver runs the body of an `if` not taken, masked, and a loop's body only once.
    bool sliced = frame.counts.x >= FEWEST_LIGHTS_SLICED;
    for (int y = 0; y < (sliced ? int(LIGHT_TILE_SIZE) : 0); y += 2) {
      for (int x = 0; x < int(LIGHT_TILE_SIZE); x += 2) {
        vec4 four = tile_depths(origin, x, y, texel);
        slices |= depth_slice_of(volume, four.x) | depth_slice_of(volume, four.y) | depth_slice_of(volume, four.z) |
                  depth_slice_of(volume, four.w);
      }
    }
    volume.slices.x = sliced ? slices : ~0u;
  }
  uint reached = surfaces ? count_listed(volume, 0u) : 0u;
  uint listed;
  uint first = take_entries(reached, listed);
  // Where the pool holds fewer than the tile's lights, it lists those worth the most there: the
  // least worth it keeps, found by halving (light_worth_bits), is the smallest that leaves at most
  // `listed` lights. A rare frame's work: the pool grows for the next ones.
  uint least = 0u;
  uint above = 0u;
  if (listed < reached) {
    above = NO_WORTH;
    while (least < above) {
      uint middle = least + (above - least) / 2u;
      if (count_listed(volume, middle) <= listed) {
        above = middle;
      } else {
        least = middle + 1u;
      }
    }
  }
  uint count = 0u;
  uint i = 0u;
  for (; count < listed && i < frame.counts.x; ++i) {
    if (!listed_in_tile(i, volume, least)) continue;
    tile_lights[first + count] = i;
    uint group = group_of(i);
    if (group_count[group] == 0u) group_first[group] = first + count;
    ++group_count[group];
    ++count;
  }
  loops_ended_early = loops_ended_early || least < above || (count < listed && i < frame.counts.x);
  if (loops_ended_early) atomicAdd(tiles_cut, 1u);
  // Lights worth exactly the least kept may not all fit: those left out count as dropped too.
  if (count < listed) atomicAdd(dropped_pairs, listed - count);
  uint groups = 0u;
  for (uint g = 0u; g < LIGHT_GROUP_COUNT; ++g) groups |= group_count[g] > 0u ? 1u << g : 0u;
  if (bitCount(groups) > 1) atomicAdd(tiles_by_groups[groups], 1u);
  uint set = group_set_within(groups);
  uint in_set = set < LIGHT_GROUP_SETS ? group_set(set) : 0u;
  for (uint g = 0u; g < LIGHT_GROUP_COUNT; ++g) {
    publish_group_range(tile, g, group_first[g], group_count[g], (in_set & (1u << g)) == 0u);
  }
  if (set < LIGHT_GROUP_SETS) list_tile(tile, LIGHT_GROUP_COUNT + set);
}
