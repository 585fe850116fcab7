// SPDX-License-Identifier: MIT
#pragma once
// The GPU cost of the frame under given settings, split into shadow-map passes and the
// rest: what the algorithm-costs and reference tools compare between shadow algorithms.
#include <cstdint>

#include "rendergraph/device/fwd.h"
#include "systems/frame/frame_settings.h"

namespace sg {

struct FrameCost {
  double lighting_ms = 0.0;      // the median per frame of every pass but the shadow-map passes
  double shadow_maps_ms = 0.0;   // the median per frame of the passes named "shadow ..."
  double frame_ms = 0.0;         // the median GPU frame
  uint32_t shadowed_lights = 0;  // lights with a shadow map in the last frame (a sun's cascades: one)
};

// Loads settings.scene and renders `frames` headless frames of it (render_headless_frames), after
// half as many (at least 2) that warm the device up and are not counted.
FrameCost measure_frame_cost(vk::VulkanContext& context, const FrameSettings& settings, uint32_t frames);

}  // namespace sg
