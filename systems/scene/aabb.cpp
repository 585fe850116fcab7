// SPDX-License-Identifier: MIT
#include "systems/scene/aabb.h"

namespace sg::scene {

Aabb transformed(const Aabb& box, const glm::mat4& matrix) {
  Aabb result;
  if (box.empty()) return result;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 point{(corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                          (corner & 4) ? box.max.z : box.min.z};
    grow(result, glm::vec3(matrix * glm::vec4(point, 1.0f)));
  }
  return result;
}

}  // namespace sg::scene
