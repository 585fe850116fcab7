// SPDX-License-Identifier: MIT
#pragma once
// The builders behind build_scene (builtin_scenes.h), one file each, and how they place things.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "ecs/transform.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene.h"

namespace sg::scene {

struct BuiltinSceneParams;  // builtin_scenes.h

// A unit primitive scaled to `size` around `center`, turned by `yaw` about +Y.
inline ecs::LocalTransform placed(glm::vec3 center, glm::vec3 size, float yaw = 0.0f) {
  return {center, glm::angleAxis(yaw, glm::vec3(0, 1, 0)), size};
}

// A light at `position` shining towards `target` (-Z forward).
inline ecs::LocalTransform aimed(glm::vec3 position, glm::vec3 target) {
  return {position, look_rotation(position, target), glm::vec3(1.0f)};
}

Scene build_default_scene();
Scene build_stress_scene(const BuiltinSceneParams& params);
Scene build_point_room_scene();
Scene build_spot_columns_scene();

}  // namespace sg::scene
