// SPDX-License-Identifier: MIT
#include "systems/lighting/light_list_pool.h"

#include <algorithm>
#include <bit>

namespace sg {

uint64_t LightListPool::entries(uint32_t tiles, uint32_t lights) const {
  const uint64_t every = std::bit_ceil(uint64_t{tiles} * lights);
  return std::max<uint64_t>(1, std::min({max_entries_, every, std::max(sure_entries, sized_)}));
}

void LightListPool::asked(uint64_t wanted) {
  // Twice what was asked: lights that move or come into view before the next answer.
  const uint64_t fitted = std::bit_ceil(std::max<uint64_t>(2 * wanted, 1));
  if (fitted > sized_) {
    sized_ = fitted;
    frames_small_ = 0;
    return;
  }
  frames_small_ = 8 * wanted < sized_ ? frames_small_ + 1 : 0;
  if (frames_small_ >= shrink_after) {
    sized_ = fitted;
    frames_small_ = 0;
  }
}

}  // namespace sg
