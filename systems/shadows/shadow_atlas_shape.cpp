// SPDX-License-Identifier: MIT
#include "systems/shadows/shadow_atlas_shape.h"

#include <algorithm>

namespace sg::shadows {

uint64_t default_shadow_budget(const DeviceShadowLimits& device) {
  return std::clamp<uint64_t>(device.device_local_heap_bytes / 8, 64ull << 20, 2ull << 30);
}

AtlasShape atlas_shape(uint64_t budget_bytes, const DeviceShadowLimits& device, bool static_layers) {
  uint32_t page = std::min(largest_atlas_page, device.max_image_dimension);
  // What the budget pays for a page, and what a page takes of one allocation (the image, or the
  // static layers' buffer, which a shader also binds whole).
  const auto page_cost = [&] { return uint64_t{page} * page * atlas_texel_cost(static_layers); };
  const auto page_bytes = [&] { return uint64_t{page} * page * atlas_texel_bytes; };
  while (page > smallest_atlas_page && page_cost() > budget_bytes) page /= 2;
  uint64_t pages = std::min<uint64_t>(
      {budget_bytes / page_cost(), device.max_allocation_bytes / page_bytes(), device.max_array_layers});
  if (static_layers) pages = std::min(pages, device.max_storage_buffer_bytes / page_bytes());
  AtlasShape shape{page, std::max(static_cast<uint32_t>(pages), 1u), 0};
  shape.budget_bytes = uint64_t{shape.max_pages} * page_cost();
  return shape;
}

uint32_t atlas_pages_to_create(uint32_t current, uint32_t needed, uint32_t max_pages) {
  if (needed <= current) return std::max(current, 1u);
  const uint32_t grown = current + current / 2;
  return std::min(std::max({needed, grown, 1u}), max_pages);
}

}  // namespace sg::shadows
