// SPDX-License-Identifier: MIT
#pragma once
// The copy behind uploads that write a frame slot's buffer only where it is out of date
// (GpuScene's instances, LightRecordUpload's light records): each item carries the upload that
// last changed it, each slot the upload it was last written by.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

#include "ecs/jobs/thread_pool.h"

namespace sg {

// Copies into `mapped`, a slot's buffer holding `items` as they were at upload `uploaded_at`,
// the items changed since (changed_at[i] > uploaded_at), or every one where `everything` (a new
// or grown buffer). In pieces of `piece` items on `pool`: writes into mapped GPU memory go faster
// from several cores.
template <class T>
void copy_changed_items(T* mapped, std::span<const T> items, std::span<const uint64_t> changed_at,
                        uint64_t uploaded_at, bool everything, std::size_t piece, jobs::ThreadPool* pool) {
  jobs::run_in_pieces(pool, items.size(), piece, [&](std::size_t begin, std::size_t end) {
    if (everything) {
      std::copy(items.begin() + begin, items.begin() + end, mapped + begin);
      return;
    }
    for (std::size_t i = begin; i < end; ++i) {
      if (changed_at[i] > uploaded_at) mapped[i] = items[i];
    }
  });
}

}  // namespace sg
