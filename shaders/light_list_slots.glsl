// SPDX-License-Identifier: MIT
// Lists written in light order by a workgroup whose THREADS threads each test one contiguous chunk
// of the candidates (light_tiles.comp, light_tiles_coarse.comp): each thread counts what it keeps
// in first_slot, the counts become where each thread's entries start, and each thread writes its
// chunk from there. Declare `const uint THREADS` before including this file.
#ifndef SG_LIGHT_LIST_SLOTS_GLSL
#define SG_LIGHT_LIST_SLOTS_GLSL

shared uint first_slot[THREADS];  // per thread: how many it keeps, then where its entries go

// PLACE_RUNS runs of THREADS / PLACE_RUNS threads: a thread of each run places its run's counts,
// then thread 0 places the runs, so that no thread walks every count. One thread placing 1,024
// counts made the coarse pass 0.07 ms with few lights, against 0.04 in runs; the tiles' pass, 64
// threads, took 2.53-2.61 ms in runs against 2.83-2.91 with 100,000 lights from afar (H200,
// 1920x1080, 2026-12-03).
const uint PLACE_RUNS = THREADS >= 1024u ? 32u : 8u;
const uint PLACE_RUN = THREADS / PLACE_RUNS;
shared uint run_places[PLACE_RUNS];
shared uint placed_total;

// Every thread, once each has put its count in first_slot[local]: turns the counts into where
// each thread's entries start, and returns the total. The barriers are the call's.
uint place_thread_counts(uint local) {
  barrier();
  if (local < PLACE_RUNS) {
    uint sum = 0u;
    for (uint t = local * PLACE_RUN; t < (local + 1u) * PLACE_RUN; ++t) {
      uint count = first_slot[t];
      first_slot[t] = sum;
      sum += count;
    }
    run_places[local] = sum;
  }
  barrier();
  if (local == 0u) {
    uint sum = 0u;
    for (uint r = 0u; r < PLACE_RUNS; ++r) {
      uint count = run_places[r];
      run_places[r] = sum;
      sum += count;
    }
    placed_total = sum;
  }
  barrier();
  first_slot[local] += run_places[local / PLACE_RUN];
  return placed_total;
}

// The chunk of `count` candidates that thread `local` tests: [x, y).
uvec2 thread_chunk(uint local, uint count) {
  uint chunk = (count + THREADS - 1u) / THREADS;
  uint first = min(local * chunk, count);
  return uvec2(first, min(first + chunk, count));
}

#endif
