#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sg::ecs
