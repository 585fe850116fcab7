// SPDX-License-Identifier: MIT
#include "ecs/transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace sg::ecs {

glm::mat4 to_matrix(const LocalTransform& local) {
  return glm::scale(glm::translate(glm::mat4{1.0f}, local.translation) * glm::mat4_cast(local.rotation),
                    local.scale);
}

}  // namespace sg::ecs
