// SPDX-License-Identifier: MIT
// Packing lights from their components into GPU records.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "systems/scene/camera.h"
#include "systems/shadows/gpu_light.h"

namespace sg::shadows {
namespace {

// A light at `position` whose -Z axis is turned to shine along `direction`.
ecs::WorldTransform placed(glm::vec3 position, glm::vec3 direction) {
  const glm::quat rotation = scene::look_rotation(position, position + direction);
  return {ecs::to_matrix({position, rotation, glm::vec3(1.0f)})};
}

void expect_near(glm::vec3 actual, glm::vec3 expected) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], 1e-5f) << "component " << c;
}

scene::ShadowSettings test_shadow() {
  scene::ShadowSettings shadow;
  shadow.algorithm = scene::ShadowAlgorithm::pcss_noise;
  shadow.constant_bias = 0.001f;
  shadow.slope_bias = 0.02f;
  shadow.pcf_radius = 2.5f;
  shadow.light_size = 0.4f;
  shadow.density = 0.5f;
  shadow.shadow_color = {0.1f, 0.2f, 0.3f};
  return shadow;
}

TEST(GpuLight, PointLightRecord) {
  scene::PointLight light;
  light.color = {1.0f, 0.5f, 0.25f};
  light.intensity = 3.0f;
  light.range = 7.0f;
  light.falloff = scene::FalloffMode::gltf_punctual;
  const GpuLight record = pack_light(light, placed({1, 2, 3}, {0, -1, 0}), test_shadow());
  EXPECT_EQ(record.position_range, glm::vec4(1, 2, 3, 7));
  EXPECT_EQ(record.color_intensity, glm::vec4(1.0f, 0.5f, 0.25f, 3.0f));
  EXPECT_EQ(record.info.x, 0u);
  EXPECT_EQ(record.info.y, 1u | 0xFFu << light_mask_shift);
  EXPECT_EQ(algorithm_of(record), scene::ShadowAlgorithm::pcss_noise);
  EXPECT_EQ(record.info.w, no_shadow_map);
  EXPECT_EQ(record.shadow_bias, glm::vec4(0.001f, 0.02f, 2.5f, 0.4f));
  EXPECT_EQ(record.shadow_color_density, glm::vec4(0.1f, 0.2f, 0.3f, 0.5f));
}

TEST(GpuLight, SpotLightRecord) {
  scene::SpotLight light;
  light.range = 12.0f;
  light.inner_cone = glm::radians(15.0f);
  light.outer_cone = glm::radians(30.0f);
  const glm::vec3 direction = glm::normalize(glm::vec3(1, -2, 0));
  const GpuLight record = pack_light(light, placed({0, 4, 0}, direction), test_shadow());
  EXPECT_EQ(record.position_range, glm::vec4(0, 4, 0, 12));
  expect_near(glm::vec3(record.direction_type), direction);
  EXPECT_NEAR(record.shape.x, std::cos(glm::radians(15.0f)), 1e-6f);
  EXPECT_NEAR(record.shape.y, std::cos(glm::radians(30.0f)), 1e-6f);
  EXPECT_EQ(record.info.x, 1u);
  EXPECT_EQ(record.info.y, 0xFFu << light_mask_shift);
  EXPECT_EQ(algorithm_of(record), scene::ShadowAlgorithm::pcss_noise);
  EXPECT_EQ(record.info.w, no_shadow_map);
}

// A light's kernel sizes ride above its algorithm in info.z, held within their limits.
TEST(GpuLight, KernelSizesRideAboveTheAlgorithm) {
  scene::ShadowSettings shadow = test_shadow();
  shadow.algorithm = scene::ShadowAlgorithm::pcss_noise;
  shadow.kernel = {.pcf_half_width = 3, .blocker_taps = 5, .filter_taps = 32, .noise_taps = 8};
  const GpuLight light = pack_light(scene::SpotLight{}, placed({0, 4, 0}, {0, -1, 0}), shadow);
  EXPECT_EQ(algorithm_of(light), scene::ShadowAlgorithm::pcss_noise);
  EXPECT_EQ(light.info.z, 4u | 3u << kernel_pcf_shift | 4u << kernel_blocker_shift |
                              31u << kernel_filter_shift | 1u << kernel_noise_shift);
  shadow.kernel = {.pcf_half_width = 9, .blocker_taps = 0, .filter_taps = 99, .noise_taps = 4};
  const GpuLight held = pack_light(scene::SpotLight{}, placed({0, 4, 0}, {0, -1, 0}), shadow);
  EXPECT_EQ(held.info.z, 4u | 3u << kernel_pcf_shift | 0u << kernel_blocker_shift |
                             31u << kernel_filter_shift | 2u << kernel_noise_shift);
}

// The light mask shares info.y with the falloff, and the contact length has direction_type.w.
TEST(GpuLight, MaskAndContactLengthRideInSpareBits) {
  scene::ShadowSettings shadow = test_shadow();
  shadow.light_mask = 0x5A;
  shadow.contact_length = 0.3f;
  scene::PointLight point;
  point.falloff = scene::FalloffMode::gltf_punctual;
  const GpuLight bulb = pack_light(point, placed({0, 1, 0}, {0, -1, 0}), shadow);
  EXPECT_EQ(bulb.info.y, 1u | 0x5Au << light_mask_shift);
  EXPECT_EQ(bulb.direction_type.w, 0.3f);
  const GpuLight sun = pack_light(scene::DirectionalLight{}, placed({0, 9, 0}, {0, -1, 0}), shadow);
  EXPECT_EQ(sun.info.y, 0x5Au << light_mask_shift);
  EXPECT_EQ(sun.direction_type.w, 0.3f) << "kept beside the direction";
}

TEST(GpuLight, DirectionalLightRecord) {
  scene::DirectionalLight light;
  light.intensity = 2.0f;
  const glm::vec3 direction = glm::normalize(glm::vec3(-1, -3, 1));
  const GpuLight record = pack_light(light, placed({5, 5, 5}, direction), test_shadow());
  expect_near(glm::vec3(record.direction_type), direction);
  EXPECT_EQ(record.position_range.w, 0.0f) << "no range";
  EXPECT_EQ(record.info.x, 2u);
}

// A lighting pass's light types: the type's bit, but a directional light with cascades has a bit
// of its own, so that a pass of such lights alone holds no single-map lookup.
TEST(GpuLight, CascadedDirectionalLightsHaveATypeBitOfTheirOwn) {
  GpuLight sun = pack_light(scene::DirectionalLight{}, placed({0, 9, 0}, {0, -1, 0}), test_shadow());
  EXPECT_EQ(light_type_bits(sun), 1u << uint32_t(GpuLightType::directional));
  sun.info.w = cascaded_shadow_maps;
  EXPECT_EQ(light_type_bits(sun), 1u << cascaded_type_bit);
  EXPECT_NE(light_type_bits(sun) & all_light_type_bits, 0u);
  const GpuLight spot = pack_light(scene::SpotLight{}, placed({0, 9, 0}, {0, -1, 0}), test_shadow());
  EXPECT_EQ(light_type_bits(spot), 1u << uint32_t(GpuLightType::spot));
}

TEST(GpuLight, CylinderLightRecord) {
  scene::CylinderLight light;
  light.inner_radius = 0.25f;
  light.outer_radius = 0.75f;
  const GpuLight record = pack_light(light, placed({0, 3, 1}, {0, -1, 0}), test_shadow());
  EXPECT_EQ(record.position_range, glm::vec4(0, 3, 1, 0));
  expect_near(glm::vec3(record.direction_type), {0, -1, 0});
  EXPECT_EQ(record.shape.z, 0.25f);
  EXPECT_EQ(record.shape.w, 0.75f);
  EXPECT_EQ(record.info.x, 3u);
}

TEST(GpuLight, ShadowMapPlacementAndCamera) {
  GpuLight record = pack_light(scene::SpotLight{}, placed({0, 4, 0}, {0, -1, 0}), test_shadow());
  const LightView view = spot_light_view({0, 4, 0}, {0, -1, 0}, glm::radians(45.0f), 10.0f);
  set_shadow_map(record, 3, {0.5f, 0.25f, 0.25f, 0.25f}, 512, view);
  EXPECT_EQ(record.info.w, 3u);
  EXPECT_EQ(record.shadow_rect, glm::vec4(0.5f, 0.25f, 0.25f, 0.25f));
  EXPECT_EQ(record.shadow_depth, glm::vec4(view.near, 10.0f, 1.0f / 512.0f, 0.0f));
  EXPECT_EQ(record.shadow_matrix, view.view_projection());

  scene::Aabb bounds;
  scene::grow(bounds, glm::vec3(-1.0f));
  scene::grow(bounds, glm::vec3(1.0f));
  set_shadow_map(record, 0, {0, 0, 1, 1}, 1024, directional_light_view({0, -1, 0}, bounds));
  EXPECT_EQ(record.shadow_depth.w, 1.0f) << "orthographic";
}

TEST(GpuLight, ShadowCubePlacement) {
  GpuLight record = pack_light(scene::PointLight{}, placed({0, 1, 0}, {0, 0, -1}), test_shadow());
  const std::array<glm::vec2, 6> faces{glm::vec2(0.0f, 0.0f), glm::vec2(0.25f, 0.0f), glm::vec2(0.5f, 0.0f),
                                       glm::vec2(0.0f, 0.5f), glm::vec2(0.25f, 0.5f), glm::vec2(0.5f, 0.5f)};
  set_shadow_cube(record, 5, faces, 0.25f, 256, {0.0f, 0.5f, 0.0f, 10.0f});
  EXPECT_EQ(record.info.w, 5u);
  EXPECT_EQ(record.shadow_depth, glm::vec4(shadow_near_plane(10.0f), 10.0f, 1.0f / 256.0f, 0.0f));
  EXPECT_EQ(record.shadow_rect, glm::vec4(0.0f, 0.0f, 0.25f, 0.25f));
  // The faces' origins two a column, as shadow_sampling.glsl's fetch_cube_depth reads them.
  for (int f = 0; f < 6; ++f) {
    const glm::vec4 column = record.shadow_matrix[f / 2];
    EXPECT_EQ(f % 2 == 0 ? glm::vec2(column.x, column.y) : glm::vec2(column.z, column.w), faces[f]) << f;
  }
  // Where the cube was rendered from, which may lag the light while the map is cached.
  EXPECT_EQ(record.shadow_matrix[3], glm::vec4(0.0f, 0.5f, 0.0f, 1.0f));
}

}  // namespace
}  // namespace sg::shadows
