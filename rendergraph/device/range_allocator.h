// SPDX-License-Identifier: MIT
#pragma once
// Offset allocator for one memory block: first fit over a free list sorted by offset, with
// neighbours coalesced on free. Pure bookkeeping (no Vulkan), so it is unit-tested on the CPU.
// Blocks hold a few dozen to a few thousand live ranges, where a sorted map is both simple and
// fast enough; allocation happens at load and resize time, never per draw.
#include <cstdint>
#include <map>
#include <optional>

namespace sg::vk {

class RangeAllocator {
 public:
  explicit RangeAllocator(uint64_t capacity);

  // Returns the offset of `size` bytes aligned to `alignment` (a power of two), or nothing
  // when no free range is large enough.
  std::optional<uint64_t> allocate(uint64_t size, uint64_t alignment);
  // `offset` and `size` must be those of a live allocation.
  void free(uint64_t offset, uint64_t size);

  uint64_t capacity() const { return capacity_; }
  uint64_t used() const { return used_; }
  bool empty() const { return used_ == 0; }
  // Number of disjoint free ranges; 1 for an empty block (fragmentation indicator).
  size_t free_range_count() const { return free_.size(); }

 private:
  uint64_t capacity_;
  uint64_t used_ = 0;
  std::map<uint64_t, uint64_t> free_;  // offset -> size
};

}  // namespace sg::vk
