// SPDX-License-Identifier: MIT
#pragma once
// Per-frame uploads of large record arrays.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include "ecs/jobs/thread_pool.h"
#include "rendergraph/device/frame_buffers.h"

namespace sg {

// FrameBuffers::write in pieces on `pool` (or on this thread without one): writes into mapped GPU
// memory go faster from several cores, and a thousand lights' records are half a megabyte.
// `after` follows `items` in the buffer.
template <class T>
const vk::Buffer& write_in_pieces(vk::FrameBuffers& buffers, uint32_t slot, std::span<const T> items,
                                  jobs::ThreadPool* pool, std::span<const T> after = {}) {
  const vk::Buffer& buffer = buffers.reserve(slot, items.size_bytes() + after.size_bytes());
  auto* mapped = static_cast<T*>(buffer.mapped());
  constexpr size_t piece = (std::size_t{64} << 10) / sizeof(T) + 1;  // about 64 KiB
  jobs::run_in_pieces(pool, items.size(), piece, [&](size_t begin, size_t end) {
    if (begin < end) std::memcpy(mapped + begin, items.data() + begin, (end - begin) * sizeof(T));
  });
  if (!after.empty()) std::memcpy(mapped + items.size(), after.data(), after.size_bytes());
  return buffer;
}

}  // namespace sg
