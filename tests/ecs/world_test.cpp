#include <gtest/gtest.h>

#include <stdexcept>

#include "ecs/world.h"
#include "test_components.h"

namespace sg::ecs {
namespace {

using test::Position;
using test::Velocity;

TEST(World, AddGetHasRemove) {
  World world;
  const Entity entity = world.create();
  EXPECT_FALSE(world.has<Position>(entity));
  world.add<Position>(entity, 1.0f, 2.0f);
  ASSERT_TRUE(world.has<Position>(entity));
  EXPECT_EQ(world.get<Position>(entity).y, 2.0f);
  EXPECT_FALSE(world.has<Velocity>(entity));
  EXPECT_TRUE(world.remove<Position>(entity));
  EXPECT_FALSE(world.has<Position>(entity));
  EXPECT_FALSE(world.remove<Position>(entity));
}

TEST(World, AddReplacesExistingComponent) {
  World world;
  const Entity entity = world.create();
  world.add<Position>(entity, 1.0f, 1.0f);
  world.add<Position>(entity, 3.0f, 4.0f);
  EXPECT_EQ(world.get<Position>(entity).x, 3.0f);
  EXPECT_EQ(world.query<const Position>().count(), 1u);
}

TEST(World, RemovalKeepsOtherComponentsIntact) {
  World world;
  std::vector<Entity> entities;
  for (int i = 0; i < 10; ++i) {
    entities.push_back(world.create());
    world.add<Position>(entities.back(), static_cast<float>(i), 0.0f);
  }
  world.remove<Position>(entities[0]);
  world.remove<Position>(entities[4]);
  world.remove<Position>(entities[9]);
  for (int i = 0; i < 10; ++i) {
    const Position* position = world.try_get<Position>(entities[i]);
    if (i == 0 || i == 4 || i == 9) {
      EXPECT_EQ(position, nullptr);
    } else {
      ASSERT_NE(position, nullptr);
      EXPECT_EQ(position->x, static_cast<float>(i));
    }
  }
}

TEST(World, StaleHandleIsDetected) {
  World world;
  const Entity old = world.create();
  world.add<Position>(old, 1.0f, 1.0f);
  ASSERT_TRUE(world.destroy(old));
  const Entity reused = world.create();
  world.add<Position>(reused, 7.0f, 7.0f);
  ASSERT_EQ(reused.index, old.index);

  EXPECT_FALSE(world.alive(old));
  EXPECT_FALSE(world.has<Position>(old));
  EXPECT_EQ(world.try_get<Position>(old), nullptr);
  EXPECT_THROW(world.get<Position>(old), std::out_of_range);
  EXPECT_THROW(world.get_mut<Position>(old), std::out_of_range);
  EXPECT_THROW(world.add<Velocity>(old), std::invalid_argument);
  EXPECT_FALSE(world.remove<Position>(old));
  EXPECT_FALSE(world.destroy(old));
  EXPECT_EQ(world.get<Position>(reused).x, 7.0f);
}

TEST(World, DestroyRemovesEveryComponent) {
  World world;
  world.destroy(test::spawn_moving(world));
  EXPECT_EQ(world.entity_count(), 0u);
  EXPECT_EQ(world.query<const Position>().count(), 0u);
  EXPECT_EQ(world.query<const Velocity>().count(), 0u);
}

TEST(World, GetMutWritesThrough) {
  World world;
  const Entity entity = test::spawn_still(world);
  world.get_mut<Position>(entity).x = 5.0f;
  EXPECT_EQ(world.get<Position>(entity).x, 5.0f);
}

}  // namespace
}  // namespace sg::ecs
