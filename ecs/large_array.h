// SPDX-License-Identifier: MIT
#pragma once
// Memory for the ECS's large arrays (component pools, sparse indices, change ticks, entity
// slots). From 2 MiB up an array gets 2 MiB-aligned memory of its own that the kernel is asked to
// back with transparent huge pages, so a million new entities cost a few dozen page faults
// instead of tens of thousands: faults were most of what creating them cost (ecs/README.md).
// Smaller arrays, and every array off Linux or where huge pages are off, get plain memory.
#include <cstddef>
#include <vector>

namespace sg::ecs {

void* allocate_large_array(std::size_t bytes, std::size_t alignment);
void free_large_array(void* memory, std::size_t bytes, std::size_t alignment) noexcept;

template <typename T>
struct LargeArrayAllocator {
  using value_type = T;
  LargeArrayAllocator() = default;
  template <typename U>
  LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}
  T* allocate(std::size_t count) {
    return static_cast<T*>(allocate_large_array(count * sizeof(T), alignof(T)));
  }
  void deallocate(T* memory, std::size_t count) noexcept {
    free_large_array(memory, count * sizeof(T), alignof(T));
  }
  template <typename U>
  bool operator==(const LargeArrayAllocator<U>&) const noexcept {
    return true;
  }
};

template <typename T>
using LargeArray = std::vector<T, LargeArrayAllocator<T>>;

}  // namespace sg::ecs
