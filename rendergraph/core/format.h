// SPDX-License-Identifier: MIT
#pragma once

// The image formats the graph can describe. Each enumerator has the value of the VkFormat named
// beside it, so the executor converts with a static_cast (guarded by static_asserts).

#include <cstdint>
#include <string_view>

namespace sg::rg {

enum class Format : std::uint32_t {
  undefined = 0,        // VK_FORMAT_UNDEFINED
  rgba8_unorm = 37,     // VK_FORMAT_R8G8B8A8_UNORM
  rgba8_srgb = 43,      // VK_FORMAT_R8G8B8A8_SRGB
  bgra8_unorm = 44,     // VK_FORMAT_B8G8R8A8_UNORM
  bgra8_srgb = 50,      // VK_FORMAT_B8G8R8A8_SRGB
  rg16_sfloat = 83,     // VK_FORMAT_R16G16_SFLOAT (shadow moments)
  rgba16_sfloat = 97,   // VK_FORMAT_R16G16B16A16_SFLOAT
  rgba32_sfloat = 109,  // VK_FORMAT_R32G32B32A32_SFLOAT (exact world positions, HDR sums)
  r32_sfloat = 100,     // VK_FORMAT_R32_SFLOAT
  d16_unorm = 124,      // VK_FORMAT_D16_UNORM
  d32_sfloat = 126,     // VK_FORMAT_D32_SFLOAT
};

// Size of one texel; 0 for Format::undefined.
std::uint32_t bytes_per_texel(Format format);

// Depth formats take the depth aspect in barriers and views; all others the color aspect.
bool is_depth(Format format);

std::string_view format_name(Format format);

}  // namespace sg::rg
