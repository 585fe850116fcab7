// SPDX-License-Identifier: MIT
#pragma once

// Descriptions of the resources a graph uses, and the handles passes name them by.

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "rendergraph/core/flags.h"
#include "rendergraph/core/format.h"
#include "rendergraph/core/sync_types.h"

namespace sg::rg {

enum class ResourceKind : std::uint8_t { image, buffer };

// The queue family a pass is meant for. The plan orders all passes on one timeline, and today's
// executor records every pass on its one graphics queue whatever this says: it adds no
// semaphores, so a compute or transfer pass costs no queue switch (and gains no overlap).
enum class QueueType : std::uint8_t { graphics, compute, transfer };

std::string_view queue_name(QueueType queue);
std::string_view kind_name(ResourceKind kind);

// "Up to the last one", like VK_REMAINING_MIP_LEVELS / VK_REMAINING_ARRAY_LAYERS.
inline constexpr std::uint32_t remaining = std::numeric_limits<std::uint32_t>::max();

// Mip levels x array layers of an image. A cube-map array stores cube c's face f (+X -X +Y -Y +Z
// -Z) at layer 6c + f. Buffers have one subresource: mip 0, layer 0.
struct SubresourceRange {
  std::uint32_t base_mip = 0;
  std::uint32_t mip_count = remaining;
  std::uint32_t base_layer = 0;
  std::uint32_t layer_count = remaining;

  static constexpr SubresourceRange all() { return {}; }
  static constexpr SubresourceRange layers(std::uint32_t first, std::uint32_t count) {
    return {0, remaining, first, count};
  }
  static constexpr SubresourceRange layer(std::uint32_t index) { return layers(index, 1); }
  static constexpr SubresourceRange cube(std::uint32_t cube_index) { return layers(cube_index * 6, 6); }
  static constexpr SubresourceRange cube_face(std::uint32_t cube_index, std::uint32_t face) {
    return layer(cube_index * 6 + face);
  }
  static constexpr SubresourceRange mip(std::uint32_t level) { return {level, 1, 0, remaining}; }

  friend bool operator==(const SubresourceRange&, const SubresourceRange&) = default;
};

// Both ranges must be resolved (no `remaining` counts).
constexpr bool overlaps(const SubresourceRange& a, const SubresourceRange& b) {
  return a.base_mip < b.base_mip + b.mip_count && b.base_mip < a.base_mip + a.mip_count &&
         a.base_layer < b.base_layer + b.layer_count && b.base_layer < a.base_layer + a.layer_count;
}

// "mip 0, layer 3" or "mips 0-3, layers 6-11"; for dumps and error messages.
std::string to_string(const SubresourceRange& range);

// A 2D image, array or cube-map array (layers = 6 x cubes, cube_compatible = true).
struct ImageDesc {
  std::uint32_t width = 1;
  std::uint32_t height = 1;
  Format format = Format::undefined;
  std::uint32_t layers = 1;
  std::uint32_t mips = 1;
  bool cube_compatible = false;

  friend bool operator==(const ImageDesc&, const ImageDesc&) = default;
};

struct BufferDesc {
  std::uint64_t size = 0;

  friend bool operator==(const BufferDesc&, const BufferDesc&) = default;
};

// Creation usage inferred from a resource's declarations; values of VkImageUsageFlagBits.
enum class ImageUsage : std::uint32_t {
  none = 0,
  transfer_src = 0x1,
  transfer_dst = 0x2,
  sampled = 0x4,
  storage = 0x8,
  color_attachment = 0x10,
  depth_stencil_attachment = 0x20,
};
template <>
inline constexpr bool is_flag_enum<ImageUsage> = true;

// Values of VkBufferUsageFlagBits.
enum class BufferUsage : std::uint32_t {
  none = 0,
  transfer_src = 0x1,
  transfer_dst = 0x2,
  storage = 0x20,
  index = 0x40,
  vertex = 0x80,
  indirect = 0x100,
};
template <>
inline constexpr bool is_flag_enum<BufferUsage> = true;

// What an attachment write starts from instead of the attachment's earlier contents: the
// executor turns it into VK_ATTACHMENT_LOAD_OP_CLEAR. Color attachments use `color`, depth
// attachments `depth`. A write without one keeps the earlier contents, except a transient's first
// write, which has none (VK_ATTACHMENT_LOAD_OP_DONT_CARE): what it does not draw is undefined.
struct ClearValue {
  std::array<float, 4> color{0.0f, 0.0f, 0.0f, 0.0f};
  float depth = 1.0f;

  static constexpr ClearValue color_of(float r, float g, float b, float a = 1.0f) {
    return {{r, g, b, a}, 1.0f};
  }
  static constexpr ClearValue depth_of(float depth) { return {{}, depth}; }

  friend bool operator==(const ClearValue&, const ClearValue&) = default;
};

inline constexpr std::uint32_t invalid_index = std::numeric_limits<std::uint32_t>::max();

// One version of a resource. Writing a handle returns the next version; only the newest version
// may be read or written again, which is what keeps the graph acyclic.
template <ResourceKind Kind>
struct ResourceHandle {
  std::uint32_t index = invalid_index;
  std::uint32_t version = 0;

  constexpr bool valid() const { return index != invalid_index; }
  friend bool operator==(const ResourceHandle&, const ResourceHandle&) = default;
};

using ImageHandle = ResourceHandle<ResourceKind::image>;
using BufferHandle = ResourceHandle<ResourceKind::buffer>;

// A state for one range of an imported resource, given at import and exported after compile.
struct RangeState {
  SubresourceRange range;
  ResourceState state;

  friend bool operator==(const RangeState&, const RangeState&) = default;
};

}  // namespace sg::rg
