// SPDX-License-Identifier: MIT
#include "systems/gpu/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace sg {

glm::mat4 view_matrix(const scene::CameraPose& pose) {
  const glm::vec3 forward = glm::normalize(pose.target - pose.eye);
  return glm::lookAtRH(pose.eye, pose.target, scene::camera_up(forward, pose.up));
}

glm::mat4 projection_matrix(const scene::Camera& lens, float aspect) {
  const float a = lens.aspect > 0.0f ? lens.aspect : aspect;
  // Near and far exchanged: depth 1 at znear, 0 at zfar (camera_near_depth, camera_far_depth).
  glm::mat4 proj = glm::perspectiveRH_ZO(lens.yfov, a, lens.zfar, lens.znear);
  proj[1][1] = -proj[1][1];  // Vulkan's NDC y points down
  return proj;
}

}  // namespace sg
