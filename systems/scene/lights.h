// SPDX-License-Identifier: MIT
#pragma once
// Light components (docs/ALGORITHMS.md section 1). A light entity also carries
// LocalTransform/WorldTransform and a ShadowSettings; its position is the world matrix's
// translation and it shines down its local -Z axis (the glTF KHR_lights_punctual convention,
// used for built-in lights too). Colors are linear RGB; intensity multiplies the color.
#include <cstdint>

#include <glm/glm.hpp>

#include "ecs/transform.h"

namespace sg::scene {

// Distance falloff (docs/ALGORITHMS.md section 2.2). Built-in scenes use the linear window,
// imported glTF lights the extension's own windowed inverse square.
enum class FalloffMode : std::uint8_t {
  linear_window,  // A = max(1 - d/R, 0)
  gltf_punctual,  // A = clamp(1 - (d/R)^4, 0, 1)^2 / d^2
};

struct PointLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float range = 10.0f;  // R, world units; always finite and > 0 (see gltf_lights.h)
  FalloffMode falloff = FalloffMode::linear_window;
};

struct SpotLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float range = 10.0f;
  float inner_cone = 0.0f;                 // radians from the axis, < outer_cone
  float outer_cone = glm::radians(45.0f);  // radians, (0, pi/2]; shadow fov = 2 * outer
  FalloffMode falloff = FalloffMode::linear_window;
};

struct DirectionalLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
};

// docs/ALGORITHMS.md's "target direct" light: a beam along -Z, full strength within inner_radius
// of its axis, fading linearly to zero at outer_radius, nothing behind the light.
struct CylinderLight {
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float inner_radius = 0.5f;  // r
  float outer_radius = 1.0f;  // R > r; also the half extent of its orthographic shadow map
};

inline glm::vec3 light_position(const ecs::WorldTransform& world) { return glm::vec3(world.matrix[3]); }

// The unit direction the light travels (its world -Z axis).
inline glm::vec3 light_direction(const ecs::WorldTransform& world) {
  return glm::normalize(-glm::vec3(world.matrix[2]));
}

}  // namespace sg::scene
