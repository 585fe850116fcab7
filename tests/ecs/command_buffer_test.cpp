// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "ecs/command_buffer.h"
#include "ecs/query.h"
#include "test_components.h"

namespace sg::ecs {
namespace {

using test::Frozen;
using test::Position;
using test::Velocity;

TEST(CommandBuffer, DestroyDuringIterationIsDeferred) {
  World world;
  for (int i = 0; i < 100; ++i) world.add<Position>(world.create(), static_cast<float>(i), 0.0f);

  CommandBuffer commands(world);
  int visited = 0;
  world.query<const Position>().for_each([&](Entity entity, const Position& position) {
    ++visited;
    if (static_cast<int>(position.x) % 2 == 0) commands.destroy(entity);
  });
  EXPECT_EQ(visited, 100);
  EXPECT_EQ(world.entity_count(), 100u);

  commands.apply();
  EXPECT_TRUE(commands.empty());
  EXPECT_EQ(world.entity_count(), 50u);
  world.query<const Position>().for_each(
      [](const Position& position) { EXPECT_EQ(static_cast<int>(position.x) % 2, 1); });
}

TEST(CommandBuffer, AddRemoveAndCreateApplyInOrder) {
  World world;
  const Entity entity = world.create();
  world.add<Position>(entity);

  CommandBuffer commands(world);
  world.query<const Position>().for_each([&](Entity e, const Position&) {
    commands.add<Velocity>(e, Velocity{1.0f, 2.0f});
    commands.remove<Position>(e);
    const Entity spawned = commands.create();
    commands.add<Position>(spawned, Position{9.0f, 9.0f});
    commands.add<Frozen>(spawned, Frozen{});
  });
  EXPECT_FALSE(world.has<Velocity>(entity));
  EXPECT_TRUE(world.has<Position>(entity));

  commands.apply();
  EXPECT_EQ(world.get<Velocity>(entity).y, 2.0f);
  EXPECT_FALSE(world.has<Position>(entity));
  std::vector<Entity> spawned;
  world.query<const Position, const Frozen>().for_each(
      [&](Entity e, const Position&, const Frozen&) { spawned.push_back(e); });
  ASSERT_EQ(spawned.size(), 1u);
  EXPECT_EQ(world.get<Position>(spawned[0]).x, 9.0f);
}

TEST(CommandBuffer, CommandsForDestroyedEntitiesAreSkipped) {
  World world;
  const Entity entity = world.create();
  CommandBuffer commands(world);
  commands.destroy(entity);
  commands.destroy(entity);
  commands.add<Position>(entity, Position{});
  EXPECT_NO_THROW(commands.apply());
  EXPECT_FALSE(world.alive(entity));
  EXPECT_EQ(world.query<const Position>().count(), 0u);
}

}  // namespace
}  // namespace sg::ecs
