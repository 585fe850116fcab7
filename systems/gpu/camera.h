// SPDX-License-Identifier: MIT
#pragma once
// Camera matrices in the engine's conventions: right-handed world with +Y up, Vulkan clip
// space (y pointing down in NDC, depth in [0, 1], reversed). The camera itself is scene data: its
// lens (scene::Camera) and its placement (scene::CameraPose).
#include <glm/glm.hpp>

#include "systems/scene/camera.h"

namespace sg {

// The camera's depth is reversed: 1 at the near plane, falling towards 0 at the far plane, and 0
// where nothing was drawn (the depth buffer's clear value). Floats are densest near 0, which is
// where a perspective depth crowds distant surfaces, so every distance keeps about a float's
// relative precision. Deferred lighting rebuilds world positions from this depth: with the
// standard direction (0 at near) and znear 0.05, a floor 100-250 units away came back up to 5 cm
// off its plane, more than the shadow bias at a spot light's pool, which striped it with acne
// (stress scene, 1920x1080, 29% of a 128-texel spot light's lit pixels; lavapipe and H200 alike,
// 2026-12-01; tests/systems/shadows/camera_depth_test.cpp).
inline constexpr float camera_near_depth = 1.0f;
inline constexpr float camera_far_depth = 0.0f;

glm::mat4 view_matrix(const scene::CameraPose& pose);
// `aspect` is width / height of the viewport; the lens's own aspect, when set, wins.
glm::mat4 projection_matrix(const scene::Camera& lens, float aspect);

}  // namespace sg
