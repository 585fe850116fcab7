// SPDX-License-Identifier: MIT
#pragma once
// The GPU record of one light: all lights of a frame are one array of GpuLight in one storage
// buffer, read by the lighting shaders as `Light lights[]` (shaders/light_record.glsl, whose
// field comments say what each component holds). tests/systems/shadows/light_record_layout_test.cpp
// checks every offset against glslang's reflection of the shader declaration.
#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "ecs/transform.h"
#include "systems/scene/lights.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/light_views.h"

namespace sg::shadows {

// info.x; the values of LIGHT_* in light_record.glsl.
enum class GpuLightType : std::uint32_t { point = 0, spot = 1, directional = 2, cylinder = 3 };

// info.y's bits 8 to 15: the layers the light lights (ShadowSettings::light_mask); bits 0 to 7
// its falloff (LIGHT_MASK_SHIFT in light_record.glsl).
inline constexpr std::uint32_t light_mask_shift = 8;
// info.z: the algorithm in bits 0 to 7, then the kernel's sizes (ShadowKernel): the pcf half
// width, the pcss blocker and filter taps less one, and log2 of the noise taps' stride through
// the 16 (the KERNEL_* shifts of light_record.glsl).
inline constexpr std::uint32_t kernel_pcf_shift = 8;       // 2 bits
inline constexpr std::uint32_t kernel_blocker_shift = 10;  // 4 bits
inline constexpr std::uint32_t kernel_filter_shift = 14;   // 5 bits
inline constexpr std::uint32_t kernel_noise_shift = 19;    // 2 bits

// info.w of a light that casts no shadow (NO_SHADOW_MAP in light_record.glsl).
inline constexpr std::uint32_t no_shadow_map = 0xFFFFFFFFu;
// info.w of a directional light whose maps are cascades (CASCADED_SHADOW_MAPS): each has a record
// of its own (FrameLights::cascades), shape.x the first one's index and shape.y their count.
inline constexpr std::uint32_t cascaded_shadow_maps = 0xFFFFFFFEu;

struct GpuLight {
  glm::vec4 position_range{0.0f};
  glm::vec4 direction_type{0.0f};
  glm::uvec4 info{0u, 0u, 0u, no_shadow_map};  // type, falloff, algorithm, shadow map index
  glm::vec4 shape{0.0f};
  glm::vec4 shadow_color_density{0.0f};
  glm::vec4 shadow_bias{0.0f};
  glm::vec4 color_intensity{0.0f};
  glm::vec4 shadow_rect{0.0f, 0.0f, 1.0f, 1.0f};
  glm::vec4 shadow_depth{0.0f};
  glm::mat4 shadow_matrix{1.0f};
};
// 208 bytes: with a 224-byte record the light culling of 100,000 lights took 78 ms a frame in 4
// runs of 4, at 208 bytes 52-55 ms in 7 runs of 8 (H200, 1920x1080, stress street camera,
// 2026-12-03); new fields go in spare bits (info.y, direction_type.w). What light culling tests
// (position and range, direction, type, shape) comes first, in 64 bytes.
static_assert(sizeof(GpuLight) == 208);
static_assert(offsetof(GpuLight, direction_type) == 16);
static_assert(offsetof(GpuLight, info) == 32);
static_assert(offsetof(GpuLight, shape) == 48);
static_assert(offsetof(GpuLight, shadow_color_density) == 64);
static_assert(offsetof(GpuLight, shadow_bias) == 80);
static_assert(offsetof(GpuLight, color_intensity) == 96);
static_assert(offsetof(GpuLight, shadow_rect) == 112);
static_assert(offsetof(GpuLight, shadow_depth) == 128);
static_assert(offsetof(GpuLight, shadow_matrix) == 144);

// The shadow algorithm a record was packed with (info.z).
inline scene::ShadowAlgorithm algorithm_of(const GpuLight& light) {
  return static_cast<scene::ShadowAlgorithm>(light.info.z & ((1u << kernel_pcf_shift) - 1u));
}

// A light's bit among a lighting pass's light types (LIGHT_TYPES in lights_interface.glsl): bit
// t for GpuLightType t, but a directional light with cascades sets bit cascaded_type_bit instead,
// so that a pass holds the cascade walk only where it has such a light, and no single-map lookup
// where those are its only 2D lights (a CPU driver runs every branch a shader holds).
inline constexpr std::uint32_t cascaded_type_bit = 4;
inline constexpr std::uint32_t all_light_type_bits = (2u << cascaded_type_bit) - 1u;
inline std::uint32_t light_type_bits(const GpuLight& light) {
  return 1u << (light.info.w == cascaded_shadow_maps ? cascaded_type_bit : light.info.x);
}

// A light's record from its components: position and direction from its world transform
// (scene::light_position, scene::light_direction), parameters from the light, the shadow
// algorithm and its parameters from `shadow`. The record has no shadow map
// (info.w == no_shadow_map) until set_shadow_map or set_shadow_cube gives it one; lights whose
// ShadowSettings::casts_shadow is false are meant to stay that way.
GpuLight pack_light(const scene::PointLight& light, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow);
GpuLight pack_light(const scene::SpotLight& light, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow);
GpuLight pack_light(const scene::DirectionalLight& light, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow);
GpuLight pack_light(const scene::CylinderLight& light, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow);

// Gives a spot, directional or cylinder light its 2D map: the square region `uv_rect` (xy
// offset, zw scale, in uv of the atlas layer) of atlas layer `atlas_layer`, `resolution`
// texels wide, rendered with `view`.
void set_shadow_map(GpuLight& light, std::uint32_t atlas_layer, const glm::vec4& uv_rect,
                    std::uint32_t resolution, const LightView& view);

// Gives a point light its cube: six square tiles of `resolution` texels, all on atlas layer
// `atlas_layer`, each `tile_scale` wide in uv of the layer, face f (+X, -X, +Y, -Y, +Z, -Z)
// with its top-left corner at face_origins[f]; rendered from `position_far`'s origin out to its
// far plane w (point_light_cube; the origin may lag the light's position while the map is
// cached). Point lights need no
// shadow matrix (the shaders select the face by the major axis), so its first three columns
// carry the face origins, two faces a column, and the last the origin.
void set_shadow_cube(GpuLight& light, std::uint32_t atlas_layer, const std::array<glm::vec2, 6>& face_origins,
                     float tile_scale, std::uint32_t resolution, const glm::vec4& position_far);

}  // namespace sg::shadows
