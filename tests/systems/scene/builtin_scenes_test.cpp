// SPDX-License-Identifier: MIT
// Built-in scenes: content, parameters, determinism, animation.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "ecs/query.h"
#include "ecs/transform.h"
#include "ecs/transform_system.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene_error.h"
#include "systems/scene/scene_queries.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {
namespace {

BuiltinSceneParams small_stress(std::uint64_t seed = 7) {
  BuiltinSceneParams params;
  params.triangles = 6000;
  params.point_lights = 6;
  params.spot_lights = 4;
  params.moving_fraction = 0.5f;
  params.seed = seed;
  return params;
}

std::vector<glm::mat4> world_matrices(Scene& scene) {
  std::vector<glm::mat4> matrices;
  scene.world.query<const ecs::WorldTransform>().for_each(
      [&](const ecs::WorldTransform& world) { matrices.push_back(world.matrix); });
  return matrices;
}

TEST(BuiltinScenes, DefaultRoomHasEveryLightKindEveryAlgorithmAndACamera) {
  Scene scene = build_scene("default");
  const SceneStats stats = scene_stats(scene);
  EXPECT_GE(stats.point_lights, 2u);
  EXPECT_GE(stats.spot_lights, 2u);
  EXPECT_GE(stats.directional_lights, 1u);
  EXPECT_EQ(stats.cylinder_lights, 1u);
  const std::uint32_t lights =
      stats.point_lights + stats.spot_lights + stats.directional_lights + stats.cylinder_lights;
  EXPECT_EQ(stats.shadow_casting_lights, lights);
  std::set<ShadowAlgorithm> used;
  scene.world.query<const ShadowSettings>().for_each(
      [&](const ShadowSettings& shadow) { used.insert(shadow.algorithm); });
  EXPECT_EQ(used.size(), std::size(all_shadow_algorithms));
  EXPECT_TRUE(first_camera(scene).has_value());
  // The room: floor top at y = 0, walls 4 m high, about 20 m across.
  const Aabb bounds = scene_bounds(scene);
  EXPECT_NEAR(bounds.max.y, 4.0f, 1e-4f);
  EXPECT_NEAR(bounds.min.y, -0.2f, 1e-4f);
  EXPECT_GT(bounds.extent().x, 20.0f);
  // Primitive meshes are shared: one box and one cylinder for the whole room.
  EXPECT_EQ(scene.meshes.meshes.size(), 2u);
  EXPECT_GT(stats.mesh_instances, 15u);
}

// The one-light scenes: the triangles and the light the shadow samples of plain Vulkan renderers
// have, so a one-light frame can be timed against theirs.
TEST(BuiltinScenes, OneLightScenesHaveTheirLightAndTriangles) {
  struct Expected {
    const char* name;
    std::uint64_t triangles;
    bool point;
    ShadowAlgorithm algorithm;
    std::uint32_t resolution;
  };
  for (const Expected& expected : {Expected{"point-room", 4752, true, ShadowAlgorithm::hard, 1024},
                                   Expected{"spot-columns", 53676, false, ShadowAlgorithm::pcf, 2048}}) {
    SCOPED_TRACE(expected.name);
    Scene scene = build_scene(expected.name);
    const SceneStats stats = scene_stats(scene);
    EXPECT_EQ(stats.triangles, expected.triangles);
    EXPECT_EQ(stats.point_lights, expected.point ? 1u : 0u);
    EXPECT_EQ(stats.spot_lights, expected.point ? 0u : 1u);
    EXPECT_EQ(stats.directional_lights + stats.cylinder_lights, 0u);
    EXPECT_EQ(stats.shadow_casting_lights, 1u);
    scene.world.query<const ShadowSettings>().for_each([&](const ShadowSettings& shadow) {
      EXPECT_EQ(shadow.algorithm, expected.algorithm);
      EXPECT_EQ(shadow.resolution, expected.resolution);
      EXPECT_EQ(shadow.kernel.pcf_half_width, 1u);
    });
    EXPECT_TRUE(first_camera(scene).has_value());
  }
}

TEST(BuiltinScenes, StressMeetsTheTriangleTargetAndLightCounts) {
  Scene scene = build_scene("stress", small_stress());
  const SceneStats stats = scene_stats(scene);
  EXPECT_GE(stats.triangles, 6000u);
  EXPECT_LT(stats.triangles, 6000u + 300u);  // within one cell's furniture
  EXPECT_EQ(stats.point_lights, 6u);
  EXPECT_EQ(stats.spot_lights, 4u);
  EXPECT_EQ(stats.directional_lights, 1u);
  std::set<ShadowAlgorithm> used;
  scene.world.query<const ShadowSettings>().for_each(
      [&](const ShadowSettings& shadow) { used.insert(shadow.algorithm); });
  EXPECT_EQ(used.size(), std::size(all_shadow_algorithms));
  EXPECT_TRUE(first_camera(scene).has_value());
}

TEST(BuiltinScenes, StressScalesWithTheTarget) {
  BuiltinSceneParams large = small_stress();
  large.triangles = 60000;
  Scene scene = build_scene("stress", large);
  const std::uint64_t triangles = scene_stats(scene).triangles;
  EXPECT_GE(triangles, 60000u);
  EXPECT_LT(triangles, 60300u);
}

TEST(BuiltinScenes, StressIsDeterministicFromTheSeed) {
  Scene first = build_scene("stress", small_stress(7));
  Scene again = build_scene("stress", small_stress(7));
  Scene other = build_scene("stress", small_stress(8));
  EXPECT_EQ(world_matrices(first), world_matrices(again));
  EXPECT_NE(world_matrices(first), world_matrices(other));
}

TEST(BuiltinScenes, MovingFractionSelectsLightsAndCrates) {
  Scene scene = build_scene("stress", small_stress());
  std::uint32_t moving_lights = 0;
  scene.world.query<const OrbitMotion, const ShadowSettings>().for_each(
      [&](const OrbitMotion&, const ShadowSettings&) { ++moving_lights; });
  EXPECT_EQ(moving_lights, 5u);  // half of 10
  BuiltinSceneParams still = small_stress();
  still.moving_fraction = 0.0f;
  Scene static_scene = build_scene("stress", still);
  std::uint32_t moving = 0;
  static_scene.world.query<const OrbitMotion>().for_each([&](const OrbitMotion&) { ++moving; });
  EXPECT_EQ(moving, 0u);
}

TEST(BuiltinScenes, AnimationMovesOnlyOrbitingEntitiesAndMarksThemChanged) {
  Scene scene = build_scene("stress", small_stress());
  const ecs::Tick before = scene.world.tick();
  scene.world.advance_tick();
  animate_orbits(scene.world, 1.5f);
  std::uint32_t changed = 0;
  std::uint32_t orbiting = 0;
  scene.world.query<const ecs::LocalTransform>().changed_since<const ecs::LocalTransform>(before).for_each(
      [&](ecs::Entity entity, const ecs::LocalTransform& local) {
        ++changed;
        const OrbitMotion* orbit = scene.world.try_get<OrbitMotion>(entity);
        ASSERT_NE(orbit, nullptr);
        ++orbiting;
        const glm::vec3 offset = local.translation - orbit->center;
        EXPECT_NEAR(glm::length(offset), orbit->radius, 1e-4f);
        const float angle = orbit->phase + orbit->angular_speed * 1.5f;
        EXPECT_NEAR(offset.x, orbit->radius * std::cos(angle), 1e-4f);
      });
  EXPECT_GT(changed, 5u);  // moving lights and crates
  EXPECT_EQ(changed, orbiting);
}

// A bob moves only the height, so it combines with an orbit that sets the rest.
TEST(Motions, ABobOnAnOrbitMovesTheHeightOnly) {
  ecs::World world;
  const ecs::Entity both = world.create();
  world.add<ecs::LocalTransform>(both, ecs::LocalTransform{glm::vec3(0.0f, 2.0f, 0.0f)});
  world.add<OrbitMotion>(both, OrbitMotion{glm::vec3(1.0f, 2.0f, 1.0f), 2.0f, 1.0f, 0.0f});
  world.add<BobMotion>(both, BobMotion{2.0f, 0.5f, 3.0f, 0.25f});
  const ecs::Entity still = world.create();
  world.add<ecs::LocalTransform>(still, ecs::LocalTransform{glm::vec3(5.0f)});
  const ecs::Tick before = world.tick();
  world.advance_tick();
  animate_orbits(world, 0.5f);
  animate_bobs(world, 0.5f);
  const glm::vec3 at = world.get<ecs::LocalTransform>(both).translation;
  EXPECT_NEAR(at.x, 1.0f + 2.0f * std::cos(0.5f), 1e-5f);
  EXPECT_NEAR(at.z, 1.0f + 2.0f * std::sin(0.5f), 1e-5f);
  EXPECT_NEAR(at.y, 2.0f + 0.5f * std::sin(0.25f + 3.0f * 0.5f), 1e-5f);
  EXPECT_GE(world.change_tick<ecs::LocalTransform>(both), before + 1);
  EXPECT_EQ(world.get<ecs::LocalTransform>(still).translation, glm::vec3(5.0f));
  EXPECT_LT(world.change_tick<ecs::LocalTransform>(still), before + 1);
}

// On threads, in many small tasks, the motions write what they write serially.
TEST(Motions, ThreadsMoveEverythingAsSerialCallsDo) {
  BuiltinSceneParams params = small_stress();
  params.triangles = 200000;  // about 1,800 crates
  params.moving_fraction = 1.0f;
  Scene serial = build_scene("stress", params);
  Scene threaded = build_scene("stress", params);
  jobs::ThreadPool threads(2);
  animate_orbits(serial.world, 2.5f);
  animate_bobs(serial.world, 2.5f);
  animate_orbits(threaded.world, 2.5f, &threads);
  animate_bobs(threaded.world, 2.5f, &threads);
  std::vector<glm::vec3> a;
  std::vector<glm::vec3> b;
  serial.world.query<const ecs::LocalTransform>().for_each(
      [&](const ecs::LocalTransform& local) { a.push_back(local.translation); });
  threaded.world.query<const ecs::LocalTransform>().for_each(
      [&](const ecs::LocalTransform& local) { b.push_back(local.translation); });
  std::uint32_t orbiting = 0;
  threaded.world.query<const OrbitMotion>().for_each([&](const OrbitMotion&) { ++orbiting; });
  EXPECT_GT(orbiting, ecs::motion_entities_per_task) << "enough for several tasks";
  EXPECT_EQ(a, b);
}

TEST(BuiltinScenes, UnknownNameAndBadFractionAreRefused) {
  try {
    build_scene("cathedral");
    ADD_FAILURE() << "an unknown scene name was accepted";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("\"cathedral\": unknown (known: default, stress, point-room, spot-columns)"),
              std::string::npos)
        << error.what();
  }
  BuiltinSceneParams bad;
  bad.moving_fraction = 1.5f;
  EXPECT_THROW(build_scene("stress", bad), SceneError);
}

TEST(BuiltinScenes, LoadSceneTakesNamesOrPaths) {
  EXPECT_EQ(load_scene("default").name, "default");
  EXPECT_THROW(load_scene("/nonexistent/scene.gltf"), SceneError);
}

}  // namespace
}  // namespace sg::scene
