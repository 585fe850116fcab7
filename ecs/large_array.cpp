// SPDX-License-Identifier: MIT
#include "ecs/large_array.h"

#include <atomic>
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

// Where each new array starts within its first huge page: one of 64 cache lines of a 4 KiB page,
// in turn. Arrays that all started on a huge-page boundary had every element i at the same
// address modulo 4 KiB, and a loop reading one array while writing another at the same i is then
// held up on Intel cores, which take a load for dependent on an earlier store whose address
// matches in its low 12 bits.
std::size_t next_stagger(std::size_t alignment) {
  static std::atomic<std::size_t> arrays{0};
  const std::size_t line = arrays.fetch_add(1, std::memory_order_relaxed) * 37 % 64;
  return (line * 64 + alignment - 1) / alignment * alignment;
}

}  // namespace

#if defined(__linux__)

// A mapping of the rounded size plus one huge page, trimmed to a huge-page boundary at both ends:
// huge pages need aligned ranges.
void* allocate_large_array(std::size_t bytes, std::size_t alignment) {
  if (bytes < huge_page) return ::operator new (bytes, std::align_val_t{alignment});
  const std::size_t stagger = next_stagger(alignment);
  const std::size_t size = rounded_to_huge_pages(bytes + stagger);
  void* mapped = mmap(nullptr, size + huge_page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(mapped);
  const std::uintptr_t aligned = (start + huge_page - 1) / huge_page * huge_page;
  if (aligned > start) munmap(mapped, aligned - start);
  const std::uintptr_t end = start + size + huge_page;
  if (end > aligned + size) munmap(reinterpret_cast<void*>(aligned + size), end - (aligned + size));
  madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);  // advice only: works without
  return reinterpret_cast<void*>(aligned + stagger);
}

void free_large_array(void* memory, std::size_t bytes, std::size_t alignment) noexcept {
  if (memory == nullptr) return;
  if (bytes < huge_page) {
    // Unsized: clang before 19 declares sized deallocation only under -fsized-deallocation.
    ::operator delete (memory, std::align_val_t{alignment});
    return;
  }
  const auto start = reinterpret_cast<std::uintptr_t>(memory);
  const std::uintptr_t mapped = start / huge_page * huge_page;  // the stagger is below a huge page
  munmap(reinterpret_cast<void*>(mapped), rounded_to_huge_pages(bytes + (start - mapped)));
}

#else

void* allocate_large_array(std::size_t bytes, std::size_t alignment) {
  return ::operator new (bytes, std::align_val_t{alignment});
}

void free_large_array(void* memory, std::size_t /*bytes*/, std::size_t alignment) noexcept {
  ::operator delete (memory, std::align_val_t{alignment});
}

#endif

}  // namespace sg::ecs
