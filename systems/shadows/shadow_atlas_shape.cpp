#include "systems/shadows/shadow_atlas_shape.h"

#include <algorithm>

namespace sg::shadows {

uint64_t default_shadow_budget(const DeviceShadowLimits& device) {
  return std::clamp<uint64_t>(device.device_local_heap_bytes / 8, 64ull << 20, 2ull << 30);
}

AtlasShape atlas_shape(uint64_t budget_bytes, const DeviceShadowLimits& device, bool static_layers) {
  const uint32_t copies = static_layers ? 2 : 1;
  uint32_t page = std::min(largest_atlas_page, device.max_image_dimension);
  const auto page_bytes = [&] { return uint64_t{page} * page * atlas_texel_bytes; };
  while (page > smallest_atlas_page && copies * page_bytes() > budget_bytes) page /= 2;
  uint64_t allowed = std::min(budget_bytes / copies, device.max_allocation_bytes);
  if (static_layers) allowed = std::min(allowed, device.max_storage_buffer_bytes);
  const auto pages =
      static_cast<uint32_t>(std::min<uint64_t>(allowed / page_bytes(), device.max_array_layers));
  AtlasShape shape{page, std::max(pages, 1u), 0};
  shape.budget_bytes = uint64_t{shape.max_pages} * page_bytes() * copies;
  return shape;
}

uint32_t atlas_pages_to_create(uint32_t current, uint32_t needed, uint32_t max_pages) {
  if (needed <= current) return std::max(current, 1u);
  const uint32_t grown = current + current / 2;
  return std::min(std::max({needed, grown, 1u}), max_pages);
}

}  // namespace sg::shadows
