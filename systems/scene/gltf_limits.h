// SPDX-License-Identifier: MIT
#pragma once
// Ceilings that keep a hostile or broken file from costing unbounded memory or time. Every
// allocation the importer makes is bounded by data that actually exists in the file (checked
// before allocating) or by one of these.
#include <cstdint>

namespace sg::scene::gltf_limits {

inline constexpr std::uint64_t max_file_bytes = std::uint64_t{1} << 30;    // .gltf, .glb, .bin, image
inline constexpr std::uint32_t max_image_side = 16384;                     // pixels
inline constexpr std::uint64_t max_image_pixels = std::uint64_t{1} << 26;  // 256 MiB as RGBA8
// Accessors without a bufferView are all zeros (plus sparse values) and cost memory without
// costing file bytes, so their element count is capped.
inline constexpr std::uint64_t max_implicit_accessor_elements = std::uint64_t{1} << 24;
inline constexpr std::uint32_t max_node_depth = 1024;  // deeper hierarchies are refused

}  // namespace sg::scene::gltf_limits
