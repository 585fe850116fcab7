// SPDX-License-Identifier: MIT
#include <vector>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "ecs/hierarchy.h"
#include "ecs/query.h"
#include "ecs/transform.h"
#include "ecs/transform_system.h"

namespace sg::ecs {
namespace {

Entity spawn(World& world, glm::vec3 translation) {
  const Entity entity = world.create();
  world.add<LocalTransform>(entity, translation);
  world.add<WorldTransform>(entity);
  return entity;
}

glm::vec3 world_position(const World& world, Entity entity) {
  return glm::vec3{world.get<WorldTransform>(entity).matrix[3]};
}

TEST(TransformSystem, ComposesParentBeforeChild) {
  World world;
  // Created child-first so that storage order is not parent-first by accident.
  const Entity grandchild = spawn(world, {0.0f, 0.0f, 1.0f});
  const Entity child = spawn(world, {0.0f, 2.0f, 0.0f});
  const Entity root = spawn(world, {3.0f, 0.0f, 0.0f});
  set_parent(world, child, root);
  set_parent(world, grandchild, child);
  update_world_transforms(world, 0);
  EXPECT_EQ(world_position(world, grandchild), glm::vec3(3.0f, 2.0f, 1.0f));
}

TEST(TransformSystem, AppliesParentRotationAndScale) {
  World world;
  const Entity root = spawn(world, {0.0f, 0.0f, 0.0f});
  world.get_mut<LocalTransform>(root).rotation =
      glm::angleAxis(glm::radians(90.0f), glm::vec3{0.0f, 0.0f, 1.0f});
  world.get_mut<LocalTransform>(root).scale = glm::vec3{2.0f};
  const Entity child = spawn(world, {1.0f, 0.0f, 0.0f});
  set_parent(world, child, root);
  update_world_transforms(world, 0);
  const glm::vec3 position = world_position(world, child);
  EXPECT_NEAR(position.x, 0.0f, 1e-5f);
  EXPECT_NEAR(position.y, 2.0f, 1e-5f);
}

TEST(TransformSystem, UpdatesOnlyChangedSubtrees) {
  World world;
  const Entity moved_root = spawn(world, {1.0f, 0.0f, 0.0f});
  const Entity moved_child = spawn(world, {1.0f, 0.0f, 0.0f});
  const Entity still_root = spawn(world, {5.0f, 0.0f, 0.0f});
  const Entity still_child = spawn(world, {1.0f, 0.0f, 0.0f});
  set_parent(world, moved_child, moved_root);
  set_parent(world, still_child, still_root);
  update_world_transforms(world, 0);
  const Tick first_run = world.tick();

  world.advance_tick();
  world.get_mut<LocalTransform>(moved_root).translation.x = 10.0f;
  update_world_transforms(world, first_run);

  EXPECT_EQ(world_position(world, moved_child), glm::vec3(11.0f, 0.0f, 0.0f));
  EXPECT_EQ(world.change_tick<WorldTransform>(moved_child), world.tick());
  EXPECT_EQ(world.change_tick<WorldTransform>(still_root), first_run);
  EXPECT_EQ(world.change_tick<WorldTransform>(still_child), first_run);
}

TEST(TransformSystem, ChangedChildUnderChangedParentUsesNewParentMatrix) {
  World world;
  const Entity root = spawn(world, {1.0f, 0.0f, 0.0f});
  const Entity child = spawn(world, {1.0f, 0.0f, 0.0f});
  set_parent(world, child, root);
  update_world_transforms(world, 0);
  const Tick first_run = world.tick();

  world.advance_tick();
  // The child is written first, so it comes first in the change log.
  world.get_mut<LocalTransform>(child).translation.y = 1.0f;
  world.get_mut<LocalTransform>(root).translation.x = 4.0f;
  update_world_transforms(world, first_run);
  EXPECT_EQ(world_position(world, child), glm::vec3(5.0f, 1.0f, 0.0f));
}

TEST(TransformSystem, ReparentingAndUnparentingRecomputeSubtree) {
  World world;
  const Entity left = spawn(world, {-10.0f, 0.0f, 0.0f});
  const Entity right = spawn(world, {10.0f, 0.0f, 0.0f});
  const Entity child = spawn(world, {0.0f, 1.0f, 0.0f});
  const Entity grandchild = spawn(world, {0.0f, 0.0f, 1.0f});
  set_parent(world, child, left);
  set_parent(world, grandchild, child);
  update_world_transforms(world, 0);
  EXPECT_EQ(world_position(world, grandchild), glm::vec3(-10.0f, 1.0f, 1.0f));

  Tick last_run = world.tick();
  world.advance_tick();
  set_parent(world, child, right);
  update_world_transforms(world, last_run);
  EXPECT_EQ(world_position(world, grandchild), glm::vec3(10.0f, 1.0f, 1.0f));

  last_run = world.tick();
  world.advance_tick();
  clear_parent(world, child);
  update_world_transforms(world, last_run);
  EXPECT_EQ(world_position(world, child), glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(world_position(world, grandchild), glm::vec3(0.0f, 1.0f, 1.0f));
}

// Standalone entities take the parallel pass, the others the hierarchy's: mixed, moved and
// updated with threads, every matrix must equal a serial update from scratch.
TEST(TransformSystem, ThreadsGiveTheSerialResult) {
  World world;
  std::vector<Entity> standalone;
  for (int i = 0; i < 40000; ++i) standalone.push_back(spawn(world, {float(i), 0.0f, 0.0f}));
  const Entity root = spawn(world, {0.0f, 5.0f, 0.0f});
  const Entity child = spawn(world, {1.0f, 0.0f, 0.0f});
  const Entity lone_child = spawn(world, {0.0f, 0.0f, 2.0f});
  set_parent(world, child, root);
  set_parent(world, lone_child, standalone[6]);  // standalone[6] becomes a parent
  jobs::ThreadPool threads(1);
  update_world_transforms(world, 0, &threads);

  const Tick last_run = world.tick();
  world.advance_tick();
  // More than one parallel task's worth of changes.
  for (size_t i = 0; i < standalone.size(); ++i) {
    if (i % 5 != 4) world.get_mut<LocalTransform>(standalone[i]).translation.y = 1;
  }
  world.get_mut<LocalTransform>(root).translation.x = 4.0f;
  update_world_transforms(world, last_run, &threads);

  World& moved = world;
  std::vector<glm::mat4> threaded;
  moved.query<const WorldTransform>().for_each(
      [&](const WorldTransform& t) { threaded.push_back(t.matrix); });
  update_world_transforms(moved, 0);  // everything again, serially
  std::vector<glm::mat4> serial;
  moved.query<const WorldTransform>().for_each([&](const WorldTransform& t) { serial.push_back(t.matrix); });
  EXPECT_EQ(threaded, serial);
  EXPECT_EQ(world_position(world, standalone[3]), glm::vec3(3.0f, 1.0f, 0.0f));
  EXPECT_EQ(world_position(world, standalone[4]), glm::vec3(4.0f, 0.0f, 0.0f));
  EXPECT_EQ(world_position(world, lone_child), glm::vec3(6.0f, 1.0f, 2.0f));
  EXPECT_EQ(world_position(world, child), glm::vec3(5.0f, 5.0f, 0.0f));
}

}  // namespace
}  // namespace sg::ecs
