// SPDX-License-Identifier: MIT
#pragma once
// How small a shadow map can get before its algorithm's shadow goes wrong: the smallest size at
// which each algorithm kept every measured light within 1% misclassified pixels against the
// ray-traced reference (shadowgraph-reference) on the default, ShadowsSpot and ShadowsDirectional
// scenes, docs/QUALITY.md ("Error against the map size"). The atlas budget takes every light down
// to its floor before it takes any light below its own (ShadowRequest::quality_floor), so the
// lights whose error would grow past 1% keep their tier longest.
//
// The floors are for lights seen whole at a few hundred pixels; the importance policy still
// gives a light that covers a few dozen pixels a smaller map when the budget is not short.
#include <cstdint>

#include "systems/scene/shadow_settings.h"

namespace sg::shadows {

constexpr uint32_t quality_floor(scene::ShadowAlgorithm algorithm) {
  switch (algorithm) {
    case scene::ShadowAlgorithm::hard:
    case scene::ShadowAlgorithm::pcf:
    case scene::ShadowAlgorithm::noise: return 128;
    case scene::ShadowAlgorithm::pcss:
    case scene::ShadowAlgorithm::pcss_noise: return 64;
  }
  return 0;
}

}  // namespace sg::shadows
