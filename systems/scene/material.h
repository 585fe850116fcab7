// SPDX-License-Identifier: MIT
#pragma once
// Surface parameters of the extended Blinn model (docs/ALGORITHMS.md section 2). Each mesh
// instance entity carries its own copy, so the renderer reads it beside the instance.
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

namespace sg::scene {

inline constexpr std::uint32_t no_texture = std::numeric_limits<std::uint32_t>::max();

// How the base color's alpha (factor times texture) is read, as glTF's material.alphaMode:
// ignored (opaque), a cut-out at alpha_cutoff (mask), or the surface's coverage, blended over
// what lies behind it (blend).
enum class AlphaMode : std::uint8_t { opaque, mask, blend };

struct Material {
  glm::vec4 base_color{0.5f, 0.5f, 0.5f, 1.0f};   // linear RGBA; docs/ALGORITHMS.md's default grey
  std::uint32_t base_color_texture = no_texture;  // index into TextureLibrary; multiplies base_color
  float specular = 0.25f;                         // kS, as the foundation's built-in scene
  float shininess = 32.0f;                        // Blinn exponent s
  AlphaMode alpha_mode = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;  // mask: where alpha is below it there is no surface
  // Both faces drawn, a back face lit with its normal flipped (glTF's doubleSided); single-sided
  // surfaces show their front faces only.
  bool double_sided = false;
};

}  // namespace sg::scene
