// SPDX-License-Identifier: MIT
#pragma once
#include "systems/scene/enum_names.h"

namespace sg::shadows {

// How a shadowed light's map resolution is chosen. screen: from the size of its reach on screen
// (light_importance), at most what it requests; requested: what it requests wherever it is seen,
// to pin a light's quality or to measure a tile size at any distance. Either way the memory
// budget demotes the lights least important on screen first, and a light out of sight gets no
// tile.
enum class ShadowResolution { screen, requested };
constexpr EnumNames<ShadowResolution, 2> enum_names(ShadowResolution) {
  return {{{ShadowResolution::screen, "screen"}, {ShadowResolution::requested, "requested"}}};
}

}  // namespace sg::shadows
