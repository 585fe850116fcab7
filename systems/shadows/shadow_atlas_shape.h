// SPDX-License-Identifier: MIT
#pragma once
// The shape of the shadow atlas (systems/shadow_maps/shadow_atlas.h): square pages of page_size texels, the
// layers of one D32 2D-array image, as many as the memory budget and the device allow, and, where
// the renderer keeps static layers, a buffer of floats holding as many pages. Plain data so the
// policy is tested without a GPU.
#include <cstdint>

namespace sg::shadows {

// What the device allows, from VkPhysicalDeviceLimits and its memory properties.
struct DeviceShadowLimits {
  uint32_t max_image_dimension = 4096;         // maxImageDimension2D
  uint32_t max_array_layers = 256;             // maxImageArrayLayers
  uint64_t max_allocation_bytes = 1ull << 30;  // maxMemoryAllocationSize: one image is one allocation
  uint64_t device_local_heap_bytes = 1ull << 30;
  uint64_t max_storage_buffer_bytes = 1ull << 30;  // maxStorageBufferRange: a shader binds the buffer whole
};

struct AtlasShape {
  uint32_t page_size = 0;     // texels, a power of two
  uint32_t max_pages = 0;     // at least 1
  uint64_t budget_bytes = 0;  // what was asked for, after the device's limits
};

inline constexpr uint32_t atlas_texel_bytes = 4;  // D32_SFLOAT, or a float of the static layers
// The bytes a light's map takes in the atlas: `faces` (6 for a cube) tiles of `resolution`.
constexpr uint64_t shadow_map_bytes(uint32_t resolution, uint32_t faces) {
  return uint64_t(faces) * resolution * resolution * atlas_texel_bytes;
}
// What the budget pays for a texel of a page: its depth, and its float in the static layers
// where the renderer keeps them.
inline constexpr uint32_t atlas_texel_cost(bool static_layers) {
  return atlas_texel_bytes * (static_layers ? 2 : 1);
}
inline constexpr uint32_t largest_atlas_page = 4096;
inline constexpr uint32_t smallest_atlas_page = 256;

// The default budget: an eighth of the largest device-local heap, within 64 MiB .. 2 GiB.
uint64_t default_shadow_budget(const DeviceShadowLimits& device);

// Pages of largest_atlas_page texels (smaller when the budget cannot hold one, down to
// smallest_atlas_page), as many as `budget_bytes` holds, within maxImageArrayLayers and one
// allocation. With `static_layers`, each page is paid for twice (image and buffer) and the
// buffer stays within maxStorageBufferRange. A budget below one smallest page still gets that
// page: shadows never fail for lack of memory, they lose resolution (ShadowAtlasPlanner).
AtlasShape atlas_shape(uint64_t budget_bytes, const DeviceShadowLimits& device, bool static_layers = false);

// How many pages to create when `needed` are in use and `current` exist: none fewer than exist,
// and when growing, half again beyond the current count (capped at max_pages), so lights added
// one at a time recreate the image, and re-render every shadow, a logarithmic number of times.
uint32_t atlas_pages_to_create(uint32_t current, uint32_t needed, uint32_t max_pages);

}  // namespace sg::shadows
