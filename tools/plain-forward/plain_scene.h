// SPDX-License-Identifier: MIT
#pragma once
// A one-light scene flattened for a plain forward renderer: every instance's triangles in world
// space with its base color, the light, and the camera, as a sample renderer would hold them.
#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "systems/scene/scene.h"

namespace sg::plain_forward {

struct PlainVertex {
  glm::vec3 position;  // world space
  glm::vec3 normal;
  glm::vec3 color;  // the material's base color
  glm::vec2 specular_shininess;
};

enum class LightKind { spot, point };

struct PlainLight {
  LightKind kind = LightKind::spot;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // spot: where it shines
  float range = 10.0f;
  float cos_inner = 1.0f;  // spot
  float cos_outer = 0.0f;
  glm::vec3 color{1.0f};       // times intensity
  uint32_t resolution = 1024;  // its map's side, or each cube face's
};

struct PlainScene {
  std::vector<PlainVertex> vertices;
  std::vector<uint32_t> indices;
  PlainLight light;
  glm::mat4 camera{1.0f};  // world -> clip space at the given aspect
  glm::vec3 eye{0.0f};
};

// Throws std::runtime_error unless the scene has exactly one light, a spot or a point light
// casting a shadow, and a camera.
PlainScene flatten(const scene::Scene& scene, float aspect);

}  // namespace sg::plain_forward
