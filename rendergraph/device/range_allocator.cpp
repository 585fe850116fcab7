// SPDX-License-Identifier: MIT
#include "rendergraph/device/range_allocator.h"

#include <cassert>

namespace sg::vk {

RangeAllocator::RangeAllocator(uint64_t capacity) : capacity_(capacity) {
  if (capacity > 0) free_.emplace(0, capacity);
}

std::optional<uint64_t> RangeAllocator::allocate(uint64_t size, uint64_t alignment) {
  assert(alignment != 0 && (alignment & (alignment - 1)) == 0);
  if (size == 0) return std::nullopt;
  for (auto it = free_.begin(); it != free_.end(); ++it) {
    const uint64_t range_begin = it->first;
    const uint64_t range_end = it->first + it->second;
    const uint64_t aligned = (range_begin + alignment - 1) & ~(alignment - 1);
    if (aligned + size > range_end) continue;
    // Split the free range into the padding before and the remainder after the allocation.
    free_.erase(it);
    if (aligned > range_begin) free_.emplace(range_begin, aligned - range_begin);
    if (aligned + size < range_end) free_.emplace(aligned + size, range_end - aligned - size);
    used_ += size;
    return aligned;
  }
  return std::nullopt;
}

void RangeAllocator::free(uint64_t offset, uint64_t size) {
  assert(offset + size <= capacity_ && size <= used_);
  used_ -= size;
  auto [it, inserted] = free_.emplace(offset, size);
  assert(inserted);
  auto next = std::next(it);
  if (next != free_.end() && it->first + it->second == next->first) {
    it->second += next->second;
    free_.erase(next);
  }
  if (it != free_.begin()) {
    auto prev = std::prev(it);
    if (prev->first + prev->second == it->first) {
      prev->second += it->second;
      free_.erase(it);
    }
  }
}

}  // namespace sg::vk
