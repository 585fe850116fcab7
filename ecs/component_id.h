// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>
#include <cstdint>

namespace sg::ecs {

namespace detail {
inline std::uint32_t next_component_id() {
  static std::atomic<std::uint32_t> next{0};
  return next.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace detail

// A small dense number per component type, used to index a world's pools without hashing.
// Numbers are handed out on first use; they are the same for every world in the process.
template <typename T>
std::uint32_t component_id() {
  static const std::uint32_t id = detail::next_component_id();
  return id;
}

}  // namespace sg::ecs
