#pragma once
// Algorithms over pieces of a range on a ThreadPool, for per-frame work over thousands of lights
// or views that one thread would take too long over: an order-keeping filter and a sort.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "ecs/thread_pool.h"

namespace sg::ecs {

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

// Sorts `items` by `less`, a strict weak order, on `pool`: pieces of `piece_size` sorted
// concurrently, then merged pairwise into `scratch` and back, a round of merges a batch (the last
// round is one merge on one thread). Not stable. Without a pool, or with one piece, std::sort.
template <class T, class Less>
void sort_in_pieces(ThreadPool* pool, std::vector<T>& items, std::vector<T>& scratch, std::size_t piece_size,
                    const Less& less) {
  piece_size = std::max<std::size_t>(piece_size, 1);
  const std::size_t count = items.size();
  if (pool == nullptr || pool->thread_count() == 1 || count <= piece_size) {
    std::sort(items.begin(), items.end(), less);
    return;
  }
  run_in_pieces(pool, count, piece_size, [&](std::size_t begin, std::size_t end) {
    std::sort(items.begin() + static_cast<std::ptrdiff_t>(begin),
              items.begin() + static_cast<std::ptrdiff_t>(end), less);
  });
  scratch.resize(count);
  for (std::size_t width = piece_size; width < count; width *= 2) {
    const std::size_t merges = (count + 2 * width - 1) / (2 * width);
    run_in_pieces(pool, merges, 1, [&](std::size_t first_merge, std::size_t end_merge) {
      for (std::size_t merge = first_merge; merge < end_merge; ++merge) {
        const auto at = [](std::vector<T>& v, std::size_t i) {
          return v.begin() + static_cast<std::ptrdiff_t>(i);
        };
        const std::size_t begin = merge * 2 * width;
        const std::size_t middle = std::min(begin + width, count);
        const std::size_t end = std::min(begin + 2 * width, count);
        std::merge(at(items, begin), at(items, middle), at(items, middle), at(items, end), at(scratch, begin),
                   less);
      }
    });
    items.swap(scratch);
  }
}

}  // namespace sg::ecs
