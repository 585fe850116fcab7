// SPDX-License-Identifier: MIT
#include "rendergraph/core/format.h"

namespace sg::rg {

std::uint32_t bytes_per_texel(Format format) {
  switch (format) {
    case Format::undefined: return 0;
    case Format::d16_unorm: return 2;
    case Format::rgba8_unorm:
    case Format::rgba8_srgb:
    case Format::bgra8_unorm:
    case Format::bgra8_srgb:
    case Format::rg16_sfloat:
    case Format::r32_sfloat:
    case Format::d32_sfloat: return 4;
    case Format::rgba16_sfloat: return 8;
    case Format::rgba32_sfloat: return 16;
  }
  return 0;
}

bool is_depth(Format format) { return format == Format::d16_unorm || format == Format::d32_sfloat; }

std::string_view format_name(Format format) {
  switch (format) {
    case Format::undefined: return "undefined";
    case Format::rgba8_unorm: return "rgba8_unorm";
    case Format::rgba8_srgb: return "rgba8_srgb";
    case Format::bgra8_unorm: return "bgra8_unorm";
    case Format::bgra8_srgb: return "bgra8_srgb";
    case Format::rg16_sfloat: return "rg16_sfloat";
    case Format::rgba16_sfloat: return "rgba16_sfloat";
    case Format::rgba32_sfloat: return "rgba32_sfloat";
    case Format::r32_sfloat: return "r32_sfloat";
    case Format::d16_unorm: return "d16_unorm";
    case Format::d32_sfloat: return "d32_sfloat";
  }
  return "unknown";
}

}  // namespace sg::rg
