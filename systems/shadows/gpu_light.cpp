// SPDX-License-Identifier: MIT
#include "systems/shadows/gpu_light.h"

#include <algorithm>
#include <cmath>

namespace sg::shadows {
namespace {

std::uint32_t to_gpu(GpuLightType type) { return static_cast<std::uint32_t>(type); }
std::uint32_t to_gpu(scene::FalloffMode falloff) { return static_cast<std::uint32_t>(falloff); }
// info.z: the algorithm and its kernel's sizes, each held within its limits.
std::uint32_t to_gpu(scene::ShadowAlgorithm algorithm, const scene::ShadowKernel& kernel) {
  const std::uint32_t pcf = std::clamp(kernel.pcf_half_width, 1u, scene::max_pcf_half_width);
  const std::uint32_t blocker = std::clamp(kernel.blocker_taps, 1u, scene::max_blocker_taps) - 1u;
  const std::uint32_t filter = std::clamp(kernel.filter_taps, 1u, scene::max_filter_taps) - 1u;
  const std::uint32_t noise_stride_log2 = kernel.noise_taps >= 16 ? 0u : kernel.noise_taps >= 8 ? 1u : 2u;
  return static_cast<std::uint32_t>(algorithm) | pcf << kernel_pcf_shift | blocker << kernel_blocker_shift |
         filter << kernel_filter_shift | noise_stride_log2 << kernel_noise_shift;
}

// The fields every light type fills the same way.
GpuLight common_record(GpuLightType type, glm::vec3 color, float intensity,
                       const scene::ShadowSettings& shadow) {
  GpuLight record;
  record.color_intensity = glm::vec4(color, intensity);
  record.shadow_color_density = glm::vec4(shadow.shadow_color, shadow.density);
  record.shadow_bias =
      glm::vec4(shadow.constant_bias, shadow.slope_bias, shadow.pcf_radius, shadow.light_size);
  record.info = glm::uvec4(to_gpu(type), std::uint32_t{shadow.light_mask} << light_mask_shift,
                           to_gpu(shadow.algorithm, shadow.kernel), no_shadow_map);
  record.direction_type.w = shadow.contact_length;
  return record;
}

}  // namespace

GpuLight pack_light(const scene::PointLight& light, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow) {
  GpuLight record = common_record(GpuLightType::point, light.color, light.intensity, shadow);
  record.position_range = glm::vec4(scene::light_position(world), light.range);
  record.info.y |= to_gpu(light.falloff);
  return record;
}

GpuLight pack_light(const scene::SpotLight& light, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow) {
  GpuLight record = common_record(GpuLightType::spot, light.color, light.intensity, shadow);
  record.position_range = glm::vec4(scene::light_position(world), light.range);
  record.direction_type = glm::vec4(scene::light_direction(world), shadow.contact_length);
  record.shape = glm::vec4(std::cos(light.inner_cone), std::cos(light.outer_cone), 0.0f, 0.0f);
  record.info.y |= to_gpu(light.falloff);
  return record;
}

GpuLight pack_light(const scene::DirectionalLight& light, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow) {
  GpuLight record = common_record(GpuLightType::directional, light.color, light.intensity, shadow);
  record.direction_type = glm::vec4(scene::light_direction(world), shadow.contact_length);
  return record;
}

GpuLight pack_light(const scene::CylinderLight& light, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow) {
  GpuLight record = common_record(GpuLightType::cylinder, light.color, light.intensity, shadow);
  record.position_range = glm::vec4(scene::light_position(world), 0.0f);
  record.direction_type = glm::vec4(scene::light_direction(world), shadow.contact_length);
  record.shape = glm::vec4(0.0f, 0.0f, light.inner_radius, light.outer_radius);
  return record;
}

void set_shadow_map(GpuLight& light, std::uint32_t atlas_layer, const glm::vec4& uv_rect,
                    std::uint32_t resolution, const LightView& view) {
  light.info.w = atlas_layer;
  light.shadow_rect = uv_rect;
  light.shadow_depth =
      glm::vec4(view.near, view.far, 1.0f / float(resolution), view.orthographic ? 1.0f : 0.0f);
  light.shadow_matrix = view.view_projection();
}

void set_shadow_cube(GpuLight& light, std::uint32_t atlas_layer, const std::array<glm::vec2, 6>& face_origins,
                     float tile_scale, std::uint32_t resolution, const glm::vec4& position_far) {
  light.info.w = atlas_layer;
  light.shadow_rect = glm::vec4(0.0f, 0.0f, tile_scale, tile_scale);
  light.shadow_depth =
      glm::vec4(shadow_near_plane(position_far.w), position_far.w, 1.0f / float(resolution), 0.0f);
  light.shadow_matrix = glm::mat4(0.0f);
  for (int f = 0; f < 6; ++f) {
    light.shadow_matrix[f / 2][2 * (f % 2)] = face_origins[f].x;
    light.shadow_matrix[f / 2][2 * (f % 2) + 1] = face_origins[f].y;
  }
  light.shadow_matrix[3] = glm::vec4(glm::vec3(position_far), 1.0f);
}

}  // namespace sg::shadows
