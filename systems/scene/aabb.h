// SPDX-License-Identifier: MIT
#pragma once
// Axis-aligned bounding boxes for meshes and scenes. An empty box has min > max, so growing it
// by the first point gives that point.
#include <limits>

#include <glm/glm.hpp>

namespace sg::scene {

struct Aabb {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};

  bool empty() const { return min.x > max.x; }
  glm::vec3 center() const { return (min + max) * 0.5f; }
  glm::vec3 extent() const { return max - min; }
};

inline void grow(Aabb& box, const glm::vec3& point) {
  box.min = glm::min(box.min, point);
  box.max = glm::max(box.max, point);
}

inline void grow(Aabb& box, const Aabb& other) {
  if (other.empty()) return;
  grow(box, other.min);
  grow(box, other.max);
}

// The box around `box` after transforming it by `matrix` (its eight corners).
Aabb transformed(const Aabb& box, const glm::mat4& matrix);

}  // namespace sg::scene
