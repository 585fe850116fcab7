#include "systems/shadows/shadow_storage_size.h"

#include <algorithm>

namespace sg::shadows {
namespace {

uint32_t capacity(uint32_t needed, uint32_t current) {
  return needed <= current ? current : std::max(needed, current + current / 2);
}

ShadowArraySize fit(const ShadowArraySize& current, const ShadowArraySize& needed, uint32_t min_resolution) {
  return {std::max({needed.resolution, current.resolution, min_resolution}),
          capacity(std::max(needed.count, 1u), current.count)};
}

}  // namespace

ShadowStorageSize fit_shadow_storage(const ShadowStorageSize& current, const ShadowStorageSize& needed,
                                     uint32_t min_resolution) {
  return {fit(current.maps, needed.maps, min_resolution), fit(current.cubes, needed.cubes, min_resolution)};
}

}  // namespace sg::shadows
