// SPDX-License-Identifier: MIT
#include "ecs/large_array.h"

#include <cstdint>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace sg::ecs {

namespace {

constexpr std::size_t huge_page = std::size_t{2} << 20;

constexpr std::size_t rounded_to_huge_pages(std::size_t bytes) {
  return (bytes + huge_page - 1) / huge_page * huge_page;
}

}  // namespace

#if defined(__linux__)

// A mapping of the rounded size plus one huge page, trimmed to a huge-page boundary at both ends:
// huge pages need aligned ranges.
void* allocate_large_array(std::size_t bytes, std::size_t alignment) {
  if (bytes < huge_page) return ::operator new (bytes, std::align_val_t{alignment});
  const std::size_t size = rounded_to_huge_pages(bytes);
  void* mapped = mmap(nullptr, size + huge_page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(mapped);
  const std::uintptr_t aligned = (start + huge_page - 1) / huge_page * huge_page;
  if (aligned > start) munmap(mapped, aligned - start);
  const std::uintptr_t end = start + size + huge_page;
  if (end > aligned + size) munmap(reinterpret_cast<void*>(aligned + size), end - (aligned + size));
  void* memory = reinterpret_cast<void*>(aligned);
  madvise(memory, size, MADV_HUGEPAGE);  // advice only: without huge pages the memory still works
  return memory;
}

void free_large_array(void* memory, std::size_t bytes, std::size_t alignment) noexcept {
  if (memory == nullptr) return;
  if (bytes < huge_page) {
    ::operator delete (memory, bytes, std::align_val_t{alignment});
    return;
  }
  munmap(memory, rounded_to_huge_pages(bytes));
}

#else

void* allocate_large_array(std::size_t bytes, std::size_t alignment) {
  return ::operator new (bytes, std::align_val_t{alignment});
}

void free_large_array(void* memory, std::size_t bytes, std::size_t alignment) noexcept {
  ::operator delete (memory, bytes, std::align_val_t{alignment});
}

#endif

}  // namespace sg::ecs
