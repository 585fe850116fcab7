// SPDX-License-Identifier: MIT
#pragma once
// How the time budget's lowered tiers (ShadowTimeBudget) fall on the lights.
//
// The budget is GPU time a frame, and a map costs time only in the frames it is redrawn: a light
// that stands still among still casters keeps its map from frame to frame and costs nothing
// after its first drawing, while a moving light pays its texels every frame. Lowering both alike
// (uniform) gives up the still light's quality for no time at all.
//
// redraw_cost: a light's map, drawn in a share `rate` of frames, is lowered by the budget's tiers
// less spared_tiers(rate). Why a third of log2(1 / rate): for lights of a size on screen, the
// shadow error a light adds goes with the size of its texels on screen (1 / resolution) and its
// time with its texels redrawn a frame (rate * resolution^2), and the resolutions that spend a
// frame's time where it removes the most error make error / resolution^3 equal to the time's
// price times rate for every light: resolution in proportion to rate^(-1/3). A map redrawn every
// 8th frame is worth one tier more than one redrawn every frame.
#include <algorithm>
#include <cmath>

#include "systems/scene/enum_names.h"

namespace sg::shadows {

enum class ShadowTimePolicy { redraw_cost, uniform };
constexpr EnumNames<ShadowTimePolicy, 2> enum_names(ShadowTimePolicy) {
  return {{{ShadowTimePolicy::redraw_cost, "redraw-cost"}, {ShadowTimePolicy::uniform, "uniform"}}};
}

// A frame's weight in a light's redraw rate, which thus follows about the last 16 frames.
inline constexpr float redraw_rate_weight = 1.0f / 16.0f;
// At most this many tiers spared: a map redrawn once in 4,096 frames or less.
inline constexpr float most_spared_tiers = 4.0f;
// Maps redrawn less often than this save too little time to count as lowerable: the budget does
// not keep lowering tiers for them (lowering_saves_time, ShadowTimeBudget::Plan::lights_lowerable).
inline constexpr float least_lowerable_rate = 1.0f / 16.0f;

// Whether lowering a map drawn in a share `redraw_rate` of frames saves time enough to count as
// lowerable (ShadowTimeBudget keeps lowering tiers while some light is).
inline bool lowering_saves_time(ShadowTimePolicy policy, float redraw_rate) {
  return policy == ShadowTimePolicy::uniform || redraw_rate >= least_lowerable_rate;
}

inline float spared_tiers(ShadowTimePolicy policy, float redraw_rate) {
  if (policy == ShadowTimePolicy::uniform) return 0.0f;
  return std::min(std::log2(1.0f / std::max(redraw_rate, 0x1p-30f)) / 3.0f, most_spared_tiers);
}

}  // namespace sg::shadows
