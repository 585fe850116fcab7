// SPDX-License-Identifier: MIT
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace sg::ecs {

// Position, orientation and scale relative to the parent (or to the world for a root).
struct LocalTransform {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
};

// Written by update_world_transforms; read it, do not write it.
struct WorldTransform {
  glm::mat4 matrix{1.0f};
};

// translation * rotation * scale.
glm::mat4 to_matrix(const LocalTransform& local);

}  // namespace sg::ecs
