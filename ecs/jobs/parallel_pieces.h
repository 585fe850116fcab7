// SPDX-License-Identifier: MIT
#pragma once
// Algorithms over pieces of a range on a ThreadPool, for per-frame work over thousands of lights
// or views that one thread would take too long over: an order-keeping filter.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "ecs/jobs/thread_pool.h"

namespace sg::jobs {

// keep_in_pieces' working storage, kept by the caller so that a frame allocates nothing once it
// has grown.
struct KeepScratch {
  std::vector<unsigned char> kept;  // by index
  std::vector<std::size_t> first;   // by piece: the rank of its first kept index
};

// An order-keeping filter over [0, count), on `pool` like run_in_pieces: calls keep(i) once for
// every i, then emit(i, rank) for every i kept, rank being its place among the kept ones in
// index order, and returns how many were kept. Pieces run concurrently (keep and emit calls for
// different i must not write the same data); a caller sizes its outputs for `count` up front and
// shrinks them to the result.
template <class Keep, class Emit>
std::size_t keep_in_pieces(ThreadPool* pool, std::size_t count, std::size_t piece_size, KeepScratch& scratch,
                           const Keep& keep, const Emit& emit) {
  piece_size = std::max<std::size_t>(piece_size, 1);
  const std::size_t pieces = (count + piece_size - 1) / piece_size;
  if (pool == nullptr || pool->thread_count() == 1 || pieces <= 1) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (keep(i)) emit(i, kept++);
    }
    return kept;
  }
  // Each piece counts its own, then emits from the count of the pieces before it.
  std::vector<unsigned char>& kept = scratch.kept;
  std::vector<std::size_t>& first = scratch.first;
  kept.resize(count);
  first.assign(pieces + 1, 0);
  run_in_pieces(pool, count, piece_size, [&](std::size_t begin, std::size_t end) {
    std::size_t in_piece = 0;
    for (std::size_t i = begin; i < end; ++i) {
      kept[i] = keep(i) ? 1 : 0;
      in_piece += kept[i];
    }
    first[begin / piece_size + 1] = in_piece;
  });
  for (std::size_t piece = 0; piece < pieces; ++piece) first[piece + 1] += first[piece];
  run_in_pieces(pool, count, piece_size, [&](std::size_t begin, std::size_t end) {
    std::size_t rank = first[begin / piece_size];
    for (std::size_t i = begin; i < end; ++i) {
      if (kept[i] != 0) emit(i, rank++);
    }
  });
  return first[pieces];
}

}  // namespace sg::jobs
