#pragma once
// Surface parameters of the extended Blinn model (../shared/ALGORITHMS.md section 2). Each mesh
// instance entity carries its own copy, so the renderer reads it beside the instance.
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

namespace sg::scene {

inline constexpr std::uint32_t no_texture = std::numeric_limits<std::uint32_t>::max();

struct Material {
  glm::vec4 base_color{0.5f, 0.5f, 0.5f, 1.0f};   // linear RGBA; ALGORITHMS.md's default grey
  std::uint32_t base_color_texture = no_texture;  // index into TextureLibrary; multiplies base_color
  float specular = 0.25f;                         // kS, as the foundation's built-in scene
  float shininess = 32.0f;                        // Blinn exponent s
};

}  // namespace sg::scene
