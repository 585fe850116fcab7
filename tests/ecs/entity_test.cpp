// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <vector>

#include "ecs/entity_registry.h"

namespace sg::ecs {
namespace {

TEST(EntityRegistry, CreatesDistinctAliveHandles) {
  EntityRegistry registry;
  const Entity a = registry.create();
  const Entity b = registry.create();
  EXPECT_NE(a, b);
  EXPECT_TRUE(registry.alive(a));
  EXPECT_TRUE(registry.alive(b));
  EXPECT_EQ(registry.alive_count(), 2u);
}

TEST(EntityRegistry, DestroyedHandleIsStaleEvenAfterSlotReuse) {
  EntityRegistry registry;
  const Entity old = registry.create();
  ASSERT_TRUE(registry.destroy(old));
  const Entity reused = registry.create();
  EXPECT_EQ(reused.index, old.index);
  EXPECT_NE(reused.generation, old.generation);
  EXPECT_FALSE(registry.alive(old));
  EXPECT_TRUE(registry.alive(reused));
  EXPECT_FALSE(registry.destroy(old));
  EXPECT_TRUE(registry.alive(reused));
}

TEST(EntityRegistry, NullAndUnknownHandlesAreNotAlive) {
  EntityRegistry registry;
  EXPECT_FALSE(registry.alive(null_entity));
  EXPECT_FALSE(registry.alive(Entity{5, 0}));
  EXPECT_FALSE(registry.destroy(null_entity));
}

TEST(EntityRegistry, FreeSlotIsNotAliveUnderItsNextGeneration) {
  EntityRegistry registry;
  const Entity entity = registry.create();
  registry.destroy(entity);
  EXPECT_FALSE(registry.alive(Entity{entity.index, entity.generation + 1}));
  EXPECT_EQ(registry.alive_count(), 0u);
}

TEST(EntityRegistry, ReusesEachFreedSlotOnceLastFreedFirstThenGrows) {
  EntityRegistry registry;
  std::vector<Entity> created;
  registry.create_many(5, created);
  const std::vector<Entity> doomed{created[1], created[3], created[4], created[1]};
  EXPECT_EQ(registry.destroy_many(doomed), 3u);
  EXPECT_EQ(registry.alive_count(), 2u);
  std::vector<Entity> again;
  registry.create_many(2, again);  // two of the three free slots
  again.push_back(registry.create());
  again.push_back(registry.create());  // the free list is empty by now: a new slot
  ASSERT_EQ(again.size(), 4u);
  EXPECT_EQ(again[0].index, created[4].index);
  EXPECT_EQ(again[1].index, created[3].index);
  EXPECT_EQ(again[2].index, created[1].index);
  EXPECT_EQ(again[3].index, 5u);
  for (const Entity entity : again) EXPECT_TRUE(registry.alive(entity));
  EXPECT_FALSE(registry.alive(created[1]));
  EXPECT_EQ(registry.alive_count(), 6u);
}

}  // namespace
}  // namespace sg::ecs
