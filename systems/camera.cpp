#include "systems/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace sg {

glm::mat4 view_matrix(const Camera& camera) { return glm::lookAtRH(camera.eye, camera.target, camera.up); }

glm::mat4 projection_matrix(const Camera& camera, float aspect) {
  glm::mat4 proj = glm::perspectiveRH_ZO(camera.fov_y, aspect, camera.near_plane, camera.far_plane);
  proj[1][1] = -proj[1][1];  // Vulkan's NDC y points down
  return proj;
}

}  // namespace sg
