// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// Light culling on GPUs (light_tiles_interface.glsl says what it writes): one workgroup per
// screen tile, its threads testing side by side the lights its coarse tile lists
// (light_tiles_coarse.comp, which also bounded the tile). The list is found in rounds and kept in
// shared memory; a list longer than that holds, or one the pool holds only part of, is found
// again in chunks (light_list_slots.glsl).
#include "light_tile_lists.glsl"
#include "light_tiles_coarse.glsl"

// A GPU wants threads to test many lights at once. At least LIGHT_GROUP_COUNT, so that every light
// group has a thread. With 100,000 lights at eye height the pass took 1.63 ms with 128, 1.77 with
// 64 and 2.74 with 32; from afar 1.59 with 128 or 64 (H200, 1920x1080, 2026-12-04).
const uint THREADS = 128u;
layout(local_size_x = THREADS) in;

// Each thread's copy of what its tile tests against.
TileVolume volume;  // the tile's surfaces
uvec2 coarse[LIGHT_COARSE_SEGMENTS];  // its coarse tile's lists, a segment of the lights each:
                                      // first entry, count
bool every_light;                     // one of them did not fit its pool: every light is tested
uint quadrant_bit;                    // its quadrant's bit in those lists' entries

// Whether the k-th light the tile tests goes in its list at worth `least` (listed_in_tile), and
// which light that is: the k-th of its coarse tile's lists, one after another, tested where it
// reaches the tile's quadrant, or light k where a list did not fit its pool.
bool lists_candidate(uint k, uint least, out uint light) {
  if (every_light) {
    light = k;
    return listed_in_tile(k, volume, least);
  }
  uint first = coarse[0].x;
  bool found = false;
  for (uint segment = 1u; segment < LIGHT_COARSE_SEGMENTS; ++segment) {
    found = found || k < coarse[segment - 1u].y;
    if (!found) {
      k -= coarse[segment - 1u].y;
      first = coarse[segment].x;
    }
  }
  uint entry = coarse_lights[first + k];
  light = entry & COARSE_ENTRY_LIGHT;
  return (entry & quadrant_bit) != 0u && listed_in_tile(light, volume, least);
}

#include "light_list_slots.glsl"

// The tile's list as list_in_rounds finds it, while it fits: at eye height among 100,000 lights a
// tile lists 766 on average (H200, 1920x1080, 2026-12-03).
const uint LISTED_CAPACITY = 2048u;
shared uint listed[LISTED_CAPACITY];
// Per round, the threads whose candidate is listed (bit t for thread t), in three buffers so that
// one barrier a round suffices: each round clears the buffer two rounds ahead.
const uint MASK_WORDS = THREADS / 32u;
shared uint round_masks[3u * MASK_WORDS];

// Every thread, from the first of the workgroup's barriers: how many of the `count` candidates
// reach the tile, the first LISTED_CAPACITY of them put in `listed` in light order. A round's
// threads test neighbouring candidates, one each, and each places its light after those of the
// round's threads before it. Testing each candidate once, where chunks test each twice, took
// the pass from 2.56 to 1.60 ms from afar and from 4.17 to 1.77 at eye height among 100,000
// lights (64 threads; H200, 1920x1080, 2026-12-04).
uint list_in_rounds(uint count, uint local) {
  if (local < 3u * MASK_WORDS) round_masks[local] = 0u;
  barrier();
  uint word = local / 32u;
  uint bit = 1u << (local % 32u);
  uint listed_count = 0u;
  for (uint base = 0u, round = 0u; base < count; base += THREADS, ++round) {
    uint masks = (round % 3u) * MASK_WORDS;
    uint light = 0u;
    bool keep = base + local < count && lists_candidate(base + local, 0u, light);
    if (keep) atomicOr(round_masks[masks + word], bit);
    barrier();
    uint before = bitCount(round_masks[masks + word] & (bit - 1u));
    uint kept = 0u;
    for (uint w = 0u; w < MASK_WORDS; ++w) {
      uint bits = bitCount(round_masks[masks + w]);
      if (w < word) before += bits;
      kept += bits;
    }
    if (keep && listed_count + before < LISTED_CAPACITY) listed[listed_count + before] = light;
    listed_count += kept;
    if (local < MASK_WORDS) round_masks[((round + 2u) % 3u) * MASK_WORDS + local] = 0u;
  }
  barrier();
  return listed_count;
}

shared uint tile_first;   // the tile's first entry in the pool
shared uint tile_listed;  // how many entries it has there
shared uint tile_wanted;  // how many lights reach it
shared uint search_low;   // the least worth kept, halved towards (light_worth_bits)
shared uint search_high;
shared uint group_first[LIGHT_GROUP_COUNT];  // per group, its range in the tile's list
shared uint group_end[LIGHT_GROUP_COUNT];

// How many of the candidates in `chunk` listed_in_tile lists at worth `least`.
uint count_candidates(uvec2 chunk, uint least) {
  uint count = 0u;
  uint light;
  for (uint k = chunk.x; k < chunk.y; ++k) {
    if (lists_candidate(k, least, light)) ++count;
  }
  return count;
}

// Where the whole list is in `listed` and the pool holds it: copies it out, and finds each
// group's range where its group differs from its neighbours' (groups are contiguous in light
// order, so in the list too).
void copy_listed(uint local) {
  uint count = tile_wanted;
  for (uint j = local; j < count; j += THREADS) {
    uint i = listed[j];
    tile_lights[tile_first + j] = i;
    listed[j] = group_of(i);
  }
  barrier();
  for (uint j = local; j < count; j += THREADS) {
    uint group = listed[j];
    if (j == 0u || listed[j - 1u] != group) group_first[group] = j;
    if (j + 1u == count || listed[j + 1u] != group) group_end[group] = j + 1u;
  }
}

// Widens `group`'s range in the tile's list to hold entries [first, end).
void widen_group(uint group, uint first, uint end) {
  atomicMin(group_first[group], first);
  atomicMax(group_end[group], end);
}

// Where the list did not fit in `listed`, or the pool holds only part of it: the candidates
// again, in chunks, at the least worth that leaves at most tile_listed lights.
void list_in_chunks(uint candidates, uint local) {
  uvec2 chunk = thread_chunk(local, candidates);
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
      first_slot[local] = count_candidates(chunk, middle);
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
  }
  first_slot[local] = count_candidates(chunk, least);
  uint kept = place_thread_counts(local);
  // Lights worth exactly the least kept may not all fit: those left out count as dropped too.
  if (local == 0u && kept < tile_listed) atomicAdd(dropped_pairs, tile_listed - kept);
  // Each thread widens the ranges of the groups its lights fall in, once per run of one group.
  uint slot = first_slot[local];
  uint run_group = LIGHT_GROUP_COUNT;
  uint run_first = 0u;
  for (uint k = chunk.x; k < chunk.y && slot < tile_listed; ++k) {
    uint i;
    if (!lists_candidate(k, least, i)) continue;
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
}

void main() {
  uint local = gl_LocalInvocationIndex;
  uint tile = gl_WorkGroupID.y * frame.screen.z + gl_WorkGroupID.x;
  if (local < LIGHT_GROUP_COUNT) {
    group_first[local] = ~0u;
    group_end[local] = 0u;
  }
  volume = tile_volumes[tile];
  uint listed_coarse = 0u;
  every_light = false;
  for (uint segment = 0u; segment < LIGHT_COARSE_SEGMENTS; ++segment) {
    uint range = first_coarse_range(gl_WorkGroupID.xy) + segment;
    coarse[segment] = segment < frame.counts.w ? coarse_ranges[range] : uvec2(0u);
    every_light = every_light || coarse[segment].y == EVERY_LIGHT;
    listed_coarse += coarse[segment].y;
  }
  quadrant_bit = 1u << (COARSE_QUADRANT_SHIFT + coarse_quadrant(gl_WorkGroupID.xy % LIGHT_COARSE_SIDE));
  uint candidates = volume.sphere.w < 0.0 ? 0u : (every_light ? frame.counts.x : listed_coarse);

  // Sorted by light index, the list is the same every frame.
  uint wanted = list_in_rounds(candidates, local);
  if (local == 0u) {
    tile_first = take_entries(wanted, tile_listed);
    tile_wanted = wanted;
    search_low = 0u;
    search_high = NO_WORTH;
  }
  barrier();
  if (wanted <= LISTED_CAPACITY && tile_listed == wanted) {
    copy_listed(local);
  } else {
    list_in_chunks(candidates, local);
  }
  barrier();
  if (local < LIGHT_GROUP_COUNT) {
    uint begin = min(group_first[local], group_end[local]);
    publish_group_range_in_tile_order(tile, local, tile_first + begin, group_end[local] - begin);
  }
}
