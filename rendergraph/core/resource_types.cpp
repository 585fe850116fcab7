// SPDX-License-Identifier: MIT
#include "rendergraph/core/resource_types.h"

namespace sg::rg {
namespace {

std::string span_text(std::string_view one, std::string_view many, std::uint32_t first, std::uint32_t count) {
  if (count == remaining) return std::string(many) + " " + std::to_string(first) + "-last";
  if (count == 1) return std::string(one) + " " + std::to_string(first);
  return std::string(many) + " " + std::to_string(first) + "-" + std::to_string(first + count - 1);
}

}  // namespace

std::string_view queue_name(QueueType queue) {
  switch (queue) {
    case QueueType::graphics: return "graphics";
    case QueueType::compute: return "compute";
    case QueueType::transfer: return "transfer";
  }
  return "unknown";
}

std::string_view kind_name(ResourceKind kind) { return kind == ResourceKind::image ? "image" : "buffer"; }

std::string to_string(const SubresourceRange& range) {
  return span_text("mip", "mips", range.base_mip, range.mip_count) + ", " +
         span_text("layer", "layers", range.base_layer, range.layer_count);
}

}  // namespace sg::rg
