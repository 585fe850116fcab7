// SPDX-License-Identifier: MIT
#pragma once
// C++ mirrors of shaders/scene_interface.glsl. std430/push-constant layout: vec4-aligned
// members only, so the C++ layout matches without padding rules to remember.
#include <bit>
#include <cstdint>

#include <glm/glm.hpp>

namespace sg {

struct GpuInstance {
  glm::mat4 model;  // the normal matrix is derived from it where needed (scene.vert)
  glm::vec4 base_color_specular;
  glm::vec4 material;  // x: shininess, negated where the surface receives no shadow, y: base
                       // color texture index or -1, z: base color alpha,
                       // w: mask's alpha cutoff (0: no cut-out), transparent_cutoff if blended
  glm::uvec4 layers;   // x: MeshInstance::light_layers; yzw: 0
};
static_assert(sizeof(GpuInstance) == 112);

// A transparent material's cutoff: its shadow is cut stochastically, its alpha the share of
// texels it covers (shaders/shadow_cut_out.glsl).
inline constexpr float transparent_cutoff = -1.0f;

// Where no surface is drawn: every lighting path's lit sum starts from it.
inline constexpr glm::vec3 background_color{0.02f, 0.02f, 0.03f};

struct FrameConstants {
  glm::mat4 view_projection;
  glm::vec4 camera_position;  // xyz; w: unused
  // x: lights; y: light tiles across the screen (transparent_tiled.frag); z, w: tone_mapping's
  glm::uvec4 counts;
  glm::vec4 ambient;  // rgb: the ambient term kA * IA (RendererSettings::ambient); w: unused
};
static_assert(sizeof(FrameConstants) <= 128, "Vulkan guarantees only 128 bytes of push constants");

// `constants` for a pass that tone-maps what it lights, into the frame (the fused path, and
// transparent surfaces blended over its frame): counts.z the exposure's bits, counts.w 1.
inline FrameConstants tone_mapping(FrameConstants constants, float exposure) {
  constants.counts.z = std::bit_cast<uint32_t>(exposure);
  constants.counts.w = 1;
  return constants;
}

}  // namespace sg
