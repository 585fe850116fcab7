// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// Light culling on GPUs (light_tiles_interface.glsl says what it writes): one workgroup per
// screen tile, its threads testing side by side the lights its coarse tile lists
// (light_tiles_coarse.comp, which also bounded the tile).
#include "light_tile_lists.glsl"
#include "light_tiles_coarse.glsl"

// A GPU wants threads to test many lights at once. At least LIGHT_GROUP_COUNT, so that every light
// group has a thread.
const uint THREADS = 64u;
layout(local_size_x = THREADS) in;

#include "light_list_slots.glsl"

shared uint tile_first;   // the tile's first entry in the pool
shared uint tile_listed;  // how many entries it has there
shared uint tile_wanted;  // how many lights reach it
shared uint search_low;   // the least worth kept, halved towards (light_worth_bits)
shared uint search_high;
shared uint group_first[LIGHT_GROUP_COUNT];  // per group, its range in the tile's list
shared uint group_end[LIGHT_GROUP_COUNT];

// The k-th light the tile tests: the k-th of its coarse tile's list (`coarse`), or light k where
// that list did not fit its pool.
uint candidate(uvec2 coarse, uint k) { return coarse.y == EVERY_LIGHT ? k : coarse_lights[coarse.x + k]; }

// How many of the candidates in `chunk` listed_in_tile lists at worth `least`.
uint count_candidates(uvec2 coarse, uvec2 chunk, TileVolume volume, uint least) {
  uint count = 0u;
  for (uint k = chunk.x; k < chunk.y; ++k) {
    if (listed_in_tile(candidate(coarse, k), volume, least)) ++count;
  }
  return count;
}

// Widens `group`'s range in the tile's list to hold entries [first, end).
void widen_group(uint group, uint first, uint end) {
  atomicMin(group_first[group], first);
  atomicMax(group_end[group], end);
}

void main() {
  uint local = gl_LocalInvocationIndex;
  uint tile = gl_WorkGroupID.y * frame.screen.z + gl_WorkGroupID.x;
  if (local < LIGHT_GROUP_COUNT) {
    group_first[local] = ~0u;
    group_end[local] = 0u;
  }
  TileVolume volume = tile_volumes[tile];
  uvec2 coarse = coarse_ranges[coarse_tile_of(gl_WorkGroupID.xy)];
  uint candidates = volume.sphere.w < 0.0 ? 0u : (coarse.y == EVERY_LIGHT ? frame.counts.x : coarse.y);

  // Candidates in ordered chunks, one per thread: count, take the tile's entries of the pool, place
  // the chunks one after another and write in order, so the list is sorted by light index and the
  // same every frame.
  uvec2 chunk = thread_chunk(local, candidates);
  first_slot[local] = count_candidates(coarse, chunk, volume, 0u);
  uint sum = place_thread_counts(local);
  if (local == 0u) {
    tile_first = take_entries(sum, tile_listed);
    tile_wanted = sum;
    search_low = 0u;
    search_high = NO_WORTH;
  }
  barrier();
  // Where the pool holds fewer than the tile's lights, it lists those worth the most there: the
  // least worth it keeps, found by halving, is the smallest that leaves at most tile_listed
  // lights. A rare frame's work: the pool grows for the next ones.
  uint least = 0u;
  if (tile_listed < tile_wanted) {
    while (true) {
      uint low = search_low;
      uint high = search_high;
      if (low >= high) break;
      uint middle = low + (high - low) / 2u;
      first_slot[local] = count_candidates(coarse, chunk, volume, middle);
      uint kept = place_thread_counts(local);
      if (local == 0u) {
        if (kept <= tile_listed) {
          search_high = middle;
        } else {
          search_low = middle + 1u;
        }
      }
      barrier();
    }
    least = search_low;
    first_slot[local] = count_candidates(coarse, chunk, volume, least);
    uint kept = place_thread_counts(local);
    if (local == 0u) {
      // Lights worth exactly the least kept may not all fit: those left out count as dropped too.
      if (kept < tile_listed) atomicAdd(dropped_pairs, tile_listed - kept);
    }
    barrier();
  }
  // Groups are contiguous in light order, so in the list too: each thread widens the ranges of
  // the groups its lights fall in, once per run of one group.
  uint slot = first_slot[local];
  uint run_group = LIGHT_GROUP_COUNT;
  uint run_first = 0u;
  for (uint k = chunk.x; k < chunk.y && slot < tile_listed; ++k) {
    uint i = candidate(coarse, k);
    if (!listed_in_tile(i, volume, least)) continue;
    tile_lights[tile_first + slot] = i;
    uint group = group_of(i);
    if (group != run_group) {
      if (run_group < LIGHT_GROUP_COUNT) widen_group(run_group, run_first, slot);
      run_group = group;
      run_first = slot;
    }
    ++slot;
  }
  if (run_group < LIGHT_GROUP_COUNT) widen_group(run_group, run_first, slot);
  barrier();
  if (local < LIGHT_GROUP_COUNT) {
    uint begin = min(group_first[local], group_end[local]);
    publish_group_range(tile, local, tile_first + begin, group_end[local] - begin, true);  // no group sets
  }
}
