// SPDX-License-Identifier: MIT
#pragma once
// The window's fly camera: right mouse to look, W A S D to move, Q E down and up, the wheel for
// speed, F to frame a box (the selected light's reach, or the scene). Plain data and a function over it, so
// it is tested without a window; WindowSession reads the input from GLFW.
#include <glm/glm.hpp>

#include "systems/scene/aabb.h"
#include "systems/scene/camera.h"

namespace sg::sandbox {

// One frame's input.
struct FlyInput {
  bool look = false;            // the right mouse button is held
  glm::vec2 mouse_delta{0.0f};  // pixels the cursor moved since the last frame (y down)
  glm::vec3 move{0.0f};         // each in -1..1: x right (D - A), y up (E - Q), z forward (W - S)
  float scroll = 0.0f;          // wheel steps since the last frame (up: faster)
  bool frame_scene = false;     // F was pressed: frame the box fly() is given
};

struct FlyCamera {
  float speed = 5.0f;  // metres per second
  float radians_per_pixel = 0.003f;
  float speed_step = 1.25f;  // per wheel step
};

// Moves `pose` for `input` over `seconds`: looking turns it (yaw about world +Y, pitch held
// within 89 degrees of the horizon, roll dropped), moving follows the view (forward, right) and
// world up, F keeps the view direction and backs off until `scene` (not empty) fits a vertical
// field of view `yfov`.
void fly(FlyCamera& camera, scene::CameraPose& pose, const FlyInput& input, float seconds,
         const scene::Aabb& scene, float yfov);

}  // namespace sg::sandbox
