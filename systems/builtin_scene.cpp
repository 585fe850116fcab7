#include "systems/builtin_scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace sg {

BuiltinScene make_builtin_scene() {
  BuiltinScene scene;
  BoxInstance floor;
  floor.center = {0.0f, -0.05f, 0.0f};
  floor.half_extent = {10.0f, 0.05f, 10.0f};
  floor.material.specular = 0.1f;
  scene.boxes.push_back(floor);

  const struct {
    glm::vec3 center, half_extent, color;
    float yaw;
  } boxes[] = {
      {{-1.6f, 0.5f, -0.8f}, {0.5f, 0.5f, 0.5f}, {0.80f, 0.25f, 0.20f}, 0.3f},
      {{1.4f, 0.75f, -1.4f}, {0.4f, 0.75f, 0.4f}, {0.20f, 0.55f, 0.80f}, -0.5f},
      {{0.3f, 0.3f, 0.9f}, {0.6f, 0.3f, 0.35f}, {0.85f, 0.75f, 0.30f}, 0.9f},
      {{-3.0f, 1.25f, -3.2f}, {0.3f, 1.25f, 0.3f}, {0.70f, 0.70f, 0.70f}, 0.0f},
      {{3.2f, 1.25f, -3.0f}, {0.3f, 1.25f, 0.3f}, {0.70f, 0.70f, 0.70f}, 0.0f},
  };
  for (const auto& b : boxes) {
    BoxInstance box;
    box.center = b.center;
    box.half_extent = b.half_extent;
    box.yaw = b.yaw;
    box.material.base_color = b.color;
    box.material.specular = 0.35f;
    scene.boxes.push_back(box);
  }

  scene.sun.direction = glm::normalize(glm::vec3(-0.45f, -1.0f, -0.35f));
  scene.sun.color = {1.0f, 0.96f, 0.9f};
  scene.sun.intensity = 1.0f;
  scene.camera.eye = {0.0f, 3.2f, 6.5f};
  scene.camera.target = {0.0f, 0.3f, -0.5f};
  return scene;
}

glm::mat4 model_matrix(const BoxInstance& box) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), box.center);
  m = glm::rotate(m, box.yaw, glm::vec3(0.0f, 1.0f, 0.0f));
  return glm::scale(m, 2.0f * box.half_extent);  // the shared box mesh is 1 unit wide
}

}  // namespace sg
