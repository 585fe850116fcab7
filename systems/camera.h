#pragma once
// Camera matrices in the engine's conventions: right-handed world with +Y up, Vulkan clip
// space (y pointing down in NDC, depth in [0, 1]).
#include <glm/glm.hpp>

namespace sg {

struct Camera {
  glm::vec3 eye{0.0f, 2.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y = glm::radians(60.0f);  // radians
  float near_plane = 0.05f;
  float far_plane = 200.0f;
};

glm::mat4 view_matrix(const Camera& camera);
glm::mat4 projection_matrix(const Camera& camera, float aspect);

}  // namespace sg
