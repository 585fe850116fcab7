// SPDX-License-Identifier: MIT
// Lists written in light order by a workgroup whose THREADS threads each test one contiguous chunk
// of the candidates (light_tiles.comp, light_tiles_coarse.comp): each thread counts what it keeps
// in first_slot, one thread turns the counts into where each thread's entries start, and each
// thread writes its chunk from there. Declare `const uint THREADS` before including this file.
#ifndef SG_LIGHT_LIST_SLOTS_GLSL
#define SG_LIGHT_LIST_SLOTS_GLSL

shared uint first_slot[THREADS];  // per thread: how many it keeps, then where its entries go

// Thread 0, once each thread has put its count in first_slot: turns the counts into where each
// thread's entries start, and returns the total.
uint place_thread_counts() {
  uint sum = 0u;
  for (uint t = 0u; t < THREADS; ++t) {
    uint count = first_slot[t];
    first_slot[t] = sum;
    sum += count;
  }
  return sum;
}

// The chunk of `count` candidates that thread `local` tests: [x, y).
uvec2 thread_chunk(uint local, uint count) {
  uint chunk = (count + THREADS - 1u) / THREADS;
  uint first = min(local * chunk, count);
  return uvec2(first, min(first + chunk, count));
}

#endif
