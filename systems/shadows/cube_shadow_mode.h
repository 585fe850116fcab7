// SPDX-License-Identifier: MIT
#pragma once
#include "systems/scene/enum_names.h"

namespace sg::shadows {

// How the per-light shadow passes (ShadowPasses, --shadow-views per-light) draw a point light's
// six cube faces: in one pass whose vertex shader moves each copy of a caster into its face's
// atlas tile (layered), or in six passes, one per face.
enum class CubeShadowMode { layered, six_passes };
constexpr EnumNames<CubeShadowMode, 2> enum_names(CubeShadowMode) {
  return {{{CubeShadowMode::layered, "layered"}, {CubeShadowMode::six_passes, "six"}}};
}

}  // namespace sg::shadows
