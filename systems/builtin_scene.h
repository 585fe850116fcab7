#pragma once
// The foundation's built-in scene: a floor and some boxes under one directional light. Until
// the ECS and glTF import land it is plain data; later it becomes entities in a World.
#include <vector>

#include <glm/glm.hpp>

#include "systems/camera.h"

namespace sg {

struct Material {
  glm::vec3 base_color{0.5f};  // ALGORITHMS.md: default grey 0.5
  float specular = 0.25f;      // kS
  float shininess = 32.0f;     // Blinn exponent s
};

// An oriented box: extends half_extent from its center, turned by yaw about +Y.
struct BoxInstance {
  glm::vec3 center{0.0f};
  glm::vec3 half_extent{0.5f};
  float yaw = 0.0f;  // radians
  Material material;
};

struct DirectionalLight {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way the light travels, normalized
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
};

struct BuiltinScene {
  std::vector<BoxInstance> boxes;  // boxes[0] is the floor; its top face lies in the plane y = 0
  DirectionalLight sun;
  float ambient = 0.15f;  // kA * IA, ALGORITHMS.md's default
  scene::CameraPose camera;
  scene::Camera lens;
};

BuiltinScene make_builtin_scene();

glm::mat4 model_matrix(const BoxInstance& box);

}  // namespace sg
