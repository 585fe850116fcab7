// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant transparent TRANSPARENT_BOUNDS
// Light culling on GPUs (light_tiles_interface.glsl says what it writes): one workgroup per
// screen tile, its threads reading the tile's depths and testing the lights side by side.
#include "light_tiles_interface.glsl"

// SIDE x SIDE threads, each reading a block of the tile's depth: a GPU wants threads to test many
// lights at once. At least 4, so that every light group has a thread.
const uint SIDE = 8u;
layout(local_size_x = SIDE, local_size_y = SIDE) in;
const uint THREADS = SIDE * SIDE;
const uint BLOCK = LIGHT_TILE_SIZE / SIDE;  // pixels per thread side

shared float thread_nearest[THREADS];
shared float thread_farthest[THREADS];
shared vec4 tile_sphere;
shared bool has_surfaces;
shared uint first_slot[THREADS];  // per thread: how many it found, then where its lights go
shared uint tile_first;   // the tile's first entry in the pool
shared uint tile_listed;  // how many entries it has there
shared uint tile_wanted;  // how many lights reach it
shared uint search_low;   // the least worth kept, halved towards (light_worth_bits)
shared uint search_high;
shared uint group_first[LIGHT_GROUP_COUNT];  // per group, its range in the tile's list
shared uint group_end[LIGHT_GROUP_COUNT];

// Thread 0, once each thread has put its count in first_slot: turns the counts into where each
// thread's lights start, and returns the tile's total.
uint place_thread_counts() {
  uint sum = 0u;
  for (uint t = 0u; t < THREADS; ++t) {
    uint count = first_slot[t];
    first_slot[t] = sum;
    sum += count;
  }
  return sum;
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
  // Each thread reduces its block, then one thread their results and the tile's bound:
  // shared-memory atomics and 64 copies of the same sphere cost a CPU driver more than a short
  // serial loop.
  // Reversed depths (camera_depth.glsl): the nearest surface has the greatest.
  float nearest = CAMERA_FAR_DEPTH;
  float farthest = 1.0;
  for (uint k = 0u; k < BLOCK * BLOCK; ++k) {
    ivec2 pixel =
        ivec2(gl_WorkGroupID.xy * LIGHT_TILE_SIZE + gl_LocalInvocationID.xy * BLOCK + uvec2(k % BLOCK, k / BLOCK));
    if (pixel.x < int(frame.screen.x) && pixel.y < int(frame.screen.y)) bound_by_pixel(pixel, nearest, farthest);
  }
  thread_nearest[local] = nearest;
  thread_farthest[local] = farthest;
  barrier();
  if (local == 0u) {
    for (uint t = 1u; t < THREADS; ++t) {
      nearest = max(nearest, thread_nearest[t]);
      farthest = min(farthest, thread_farthest[t]);
    }
    bound_by_transparent_surfaces(tile, nearest, farthest);
    has_surfaces = !is_background_depth(nearest);
    tile_sphere = visible_sphere_of_tile(gl_WorkGroupID.xy, nearest, farthest);
  }
  barrier();

  // Lights in ordered chunks, one per thread: count, take the tile's entries of the pool, place
  // the chunks one after another and write in order, so the list is sorted by light index and the
  // same every frame.
  uint light_count = has_surfaces ? frame.counts.x : 0u;
  vec4 sphere = tile_sphere;
  uint chunk = (light_count + THREADS - 1u) / THREADS;
  uint first = min(local * chunk, light_count);
  uint last = min(first + chunk, light_count);
  first_slot[local] = count_listed(first, last, sphere, 0u);
  barrier();
  if (local == 0u) {
    uint sum = place_thread_counts();
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
      first_slot[local] = count_listed(first, last, sphere, middle);
      barrier();
      if (local == 0u) {
        if (place_thread_counts() <= tile_listed) {
          search_high = middle;
        } else {
          search_low = middle + 1u;
        }
      }
      barrier();
    }
    least = search_low;
    first_slot[local] = count_listed(first, last, sphere, least);
    barrier();
    if (local == 0u) {
      uint sum = place_thread_counts();
      // Lights worth exactly the least kept may not all fit: those left out count as dropped too.
      if (sum < tile_listed) atomicAdd(dropped_pairs, tile_listed - sum);
    }
    barrier();
  }
  // Groups are contiguous in light order, so in the list too: each thread widens the ranges of
  // the groups its lights fall in, once per run of one group.
  uint slot = first_slot[local];
  uint run_group = LIGHT_GROUP_COUNT;
  uint run_first = 0u;
  for (uint i = first; i < last && slot < tile_listed; ++i) {
    if (!listed_in_tile(i, sphere, least)) continue;
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
    publish_group_range(tile, local, tile_first + begin, group_end[local] - begin);
  }
}
