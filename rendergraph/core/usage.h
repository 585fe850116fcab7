// SPDX-License-Identifier: MIT
#pragma once

// What a pass does with a resource. The direction (read or write) comes from the PassBuilder call,
// so one Usage names both sides where both exist: `read(depth, Usage::depth_attachment)` is a
// read-only depth test, `write(depth, Usage::depth_attachment)` tests and writes.

#include <cstdint>
#include <optional>
#include <string_view>

#include "rendergraph/core/resource_types.h"
#include "rendergraph/core/sync_types.h"

namespace sg::rg {

enum class Usage : std::uint8_t {
  depth_attachment,  // image; read: depth test only; write: depth test and write
  color_attachment,  // image; write only (a color attachment may also be blended, so it reads)
  sampled_fragment,  // image; read only
  sampled_compute,   // image; read only
  storage_vertex,    // image or buffer; write includes read (read-modify-write)
  storage_fragment,  // image or buffer
  storage_compute,   // image or buffer
  transfer,          // image or buffer; read: copy source, write: copy/clear destination
  indirect,          // buffer; read only (draw/dispatch arguments)
  vertex,            // buffer; read only
  index,             // buffer; read only
};

enum class Direction : std::uint8_t { read, write };

// The stages, accesses and layout that `usage` implies, or nullopt when the usage cannot be used
// in that direction or on that kind of resource (for example writing a sampled image, or using a
// buffer as a depth attachment). Buffers get ImageLayout::undefined.
std::optional<ResourceState> usage_state(Usage usage, Direction direction, ResourceKind kind);

// The creation usage a declaration requires.
ImageUsage image_usage(Usage usage, Direction direction);
BufferUsage buffer_usage(Usage usage, Direction direction);

std::string_view usage_name(Usage usage);
std::string_view direction_name(Direction direction);

}  // namespace sg::rg
