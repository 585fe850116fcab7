// SPDX-License-Identifier: MIT
#include "rendergraph/core/sync_types.h"

#include <array>
#include <cstdint>
#include <string_view>
#include <utility>

namespace sg::rg {
namespace {

using BitName = std::pair<std::uint64_t, std::string_view>;

template <std::size_t N>
std::string join_bits(std::uint64_t bits, const std::array<BitName, N>& names) {
  std::string text;
  for (const auto& [bit, name] : names) {
    if ((bits & bit) == 0) continue;
    if (!text.empty()) text += '|';
    text += name;
  }
  return text.empty() ? std::string("NONE") : text;
}

constexpr std::array<BitName, 15> stage_names{{
    {0x1, "TOP_OF_PIPE"},
    {0x2, "DRAW_INDIRECT"},
    {0x8, "VERTEX_SHADER"},
    {0x80, "FRAGMENT_SHADER"},
    {0x100, "EARLY_FRAGMENT_TESTS"},
    {0x200, "LATE_FRAGMENT_TESTS"},
    {0x400, "COLOR_ATTACHMENT_OUTPUT"},
    {0x800, "COMPUTE_SHADER"},
    {0x1000, "ALL_TRANSFER"},
    {0x2000, "BOTTOM_OF_PIPE"},
    {0x4000, "HOST"},
    {0x8000, "ALL_GRAPHICS"},
    {0x10000, "ALL_COMMANDS"},
    {0x1000000000, "INDEX_INPUT"},
    {0x2000000000, "VERTEX_ATTRIBUTE_INPUT"},
}};

constexpr std::array<BitName, 17> access_names{{
    {0x1, "INDIRECT_COMMAND_READ"},
    {0x2, "INDEX_READ"},
    {0x4, "VERTEX_ATTRIBUTE_READ"},
    {0x8, "UNIFORM_READ"},
    {0x80, "COLOR_ATTACHMENT_READ"},
    {0x100, "COLOR_ATTACHMENT_WRITE"},
    {0x200, "DEPTH_STENCIL_ATTACHMENT_READ"},
    {0x400, "DEPTH_STENCIL_ATTACHMENT_WRITE"},
    {0x800, "TRANSFER_READ"},
    {0x1000, "TRANSFER_WRITE"},
    {0x2000, "HOST_READ"},
    {0x4000, "HOST_WRITE"},
    {0x8000, "MEMORY_READ"},
    {0x10000, "MEMORY_WRITE"},
    {0x100000000, "SHADER_SAMPLED_READ"},
    {0x200000000, "SHADER_STORAGE_READ"},
    {0x400000000, "SHADER_STORAGE_WRITE"},
}};

}  // namespace

std::string to_string(PipelineStage stages) {
  return join_bits(static_cast<std::uint64_t>(stages), stage_names);
}

std::string to_string(Access access) { return join_bits(static_cast<std::uint64_t>(access), access_names); }

std::string to_string(ImageLayout layout) {
  switch (layout) {
    case ImageLayout::undefined: return "UNDEFINED";
    case ImageLayout::general: return "GENERAL";
    case ImageLayout::color_attachment_optimal: return "COLOR_ATTACHMENT_OPTIMAL";
    case ImageLayout::depth_stencil_attachment_optimal: return "DEPTH_STENCIL_ATTACHMENT_OPTIMAL";
    case ImageLayout::depth_stencil_read_only_optimal: return "DEPTH_STENCIL_READ_ONLY_OPTIMAL";
    case ImageLayout::shader_read_only_optimal: return "SHADER_READ_ONLY_OPTIMAL";
    case ImageLayout::transfer_src_optimal: return "TRANSFER_SRC_OPTIMAL";
    case ImageLayout::transfer_dst_optimal: return "TRANSFER_DST_OPTIMAL";
    case ImageLayout::read_only_optimal: return "READ_ONLY_OPTIMAL";
    case ImageLayout::attachment_optimal: return "ATTACHMENT_OPTIMAL";
    case ImageLayout::present_src: return "PRESENT_SRC";
  }
  return "UNKNOWN";
}

}  // namespace sg::rg
