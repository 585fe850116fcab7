// SPDX-License-Identifier: MIT
// Real files made by others (../shared/assets), when present; skipped cleanly when absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "systems/scene/gltf_import.h"
#include "systems/scene/lights.h"
#include "systems/scene/material.h"
#include "systems/scene/node_animation.h"
#include "systems/scene/scene_queries.h"

namespace sg::scene {
namespace {

// The asset's path, or empty when the shared folder is not there.
std::string shared_asset(const std::string& relative) {
  const std::filesystem::path path = std::filesystem::path(SHADOWGRAPH_SHARED_ASSETS) / relative;
  return std::filesystem::exists(path) ? path.string() : std::string();
}

#define LOAD_SHARED_OR_SKIP(variable, relative)                                     \
  const std::string variable##_path = shared_asset(relative);                       \
  if (variable##_path.empty()) GTEST_SKIP() << "shared asset absent: " << relative; \
  Scene variable = load_gltf(variable##_path)

// The shadow test scenes: one shadow-casting light of the given kind over ~1,000 triangles.
void expect_one_light_of_kind(Scene& scene, std::uint32_t SceneStats::*kind) {
  const SceneStats stats = scene_stats(scene);
  EXPECT_EQ(stats.*kind, 1u);
  EXPECT_EQ(stats.point_lights + stats.spot_lights + stats.directional_lights + stats.cylinder_lights, 1u);
  EXPECT_EQ(stats.shadow_casting_lights, 1u);
  EXPECT_GT(stats.triangles, 1000u);
}

TEST(SharedAssets, ShadowsSpotHasOneSpotLightWithTheFilesRangeAndCones) {
  LOAD_SHARED_OR_SKIP(scene, "ShadowsSpot/shadows-spot.gltf");
  expect_one_light_of_kind(scene, &SceneStats::spot_lights);
  scene.world.query<const SpotLight, const ecs::WorldTransform>().for_each(
      [](const SpotLight& spot, const ecs::WorldTransform& world) {
        EXPECT_FLOAT_EQ(spot.range, 25.0f);
        EXPECT_NEAR(spot.inner_cone, 0.353f, 1e-3f);
        EXPECT_NEAR(spot.outer_cone, 0.393f, 1e-3f);
        EXPECT_EQ(spot.falloff, FalloffMode::gltf_punctual);
        EXPECT_LT(light_direction(world).y, -0.5f);  // the file's light looks down
      });
  // The file animates its light and the cone mesh around it: both nodes play, and the light
  // moves with its node.
  EXPECT_EQ(scene.world.query<const NodeAnimation>().count(), 2u);
  const auto light_at = [&](float time) {
    animate_nodes(scene.world, time);
    ecs::update_world_transforms(scene.world, 0);
    glm::vec3 position(0.0f);
    scene.world.query<const SpotLight, const ecs::WorldTransform>().for_each(
        [&](ecs::Entity, const SpotLight&, const ecs::WorldTransform& world) {
          position = light_position(world);
        });
    return position;
  };
  EXPECT_GT(glm::length(light_at(1.0f) - light_at(0.0f)), 0.01f);
}

TEST(SharedAssets, ShadowsDirectionalHasOneDirectionalLight) {
  LOAD_SHARED_OR_SKIP(scene, "ShadowsDirectional/shadows-directional.gltf");
  expect_one_light_of_kind(scene, &SceneStats::directional_lights);
}

TEST(SharedAssets, FoxLoadsNonIndexedSkinnedInBindPose) {
  LOAD_SHARED_OR_SKIP(scene, "Fox/Fox.glb");
  EXPECT_EQ(scene_stats(scene).triangles, 576u);
  EXPECT_FALSE(scene_bounds(scene).empty());
  bool bind_pose_warning = false;
  for (const std::string& warning : scene.warnings) {
    bind_pose_warning = bind_pose_warning || warning.find("bind pose") != std::string::npos;
  }
  EXPECT_TRUE(bind_pose_warning);
}

TEST(SharedAssets, BoxTexturedLoadsItsExternalBufferAndPng) {
  LOAD_SHARED_OR_SKIP(scene, "BoxTextured/BoxTextured.gltf");
  EXPECT_EQ(scene_stats(scene).triangles, 12u);
  ASSERT_EQ(scene.textures.textures.size(), 1u);
  const Texture& texture = scene.textures.textures[0];
  EXPECT_GT(texture.width, 0u);
  EXPECT_EQ(texture.pixels.size(), std::size_t{texture.width} * texture.height * 4);
  bool textured = false;
  scene.world.query<const Material>().for_each(
      [&](const Material& material) { textured = textured || material.base_color_texture == 0; });
  EXPECT_TRUE(textured);
}

}  // namespace
}  // namespace sg::scene
