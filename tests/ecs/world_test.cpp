// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "ecs/query.h"
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

TEST(World, LayoutStampsChangeWithEveryInsertEraseAndReorderOnly) {
  World world;
  EXPECT_EQ(world.layout_stamp<Position>(), 0u);  // no pool yet
  std::vector<Entity> entities;
  for (int i = 0; i < 3; ++i) entities.push_back(world.create());
  for (const Entity entity : entities) world.add<Position>(entity);
  for (auto it = entities.rbegin(); it != entities.rend(); ++it) world.add<Velocity>(*it);
  const uint64_t position = world.layout_stamp<Position>();
  const uint64_t velocity = world.layout_stamp<Velocity>();
  EXPECT_NE(position, 0u);
  EXPECT_NE(position, velocity);

  world.get_mut<Position>(entities[0]).x = 1.0f;  // a write is no structural change
  world.advance_tick();
  EXPECT_EQ(world.layout_stamp<Position>(), position);

  // The query finds Velocity in another order; the next tick puts it in entity order.
  world.query<const Position, const Velocity>().for_each([](const Position&, const Velocity&) {});
  world.advance_tick();
  EXPECT_EQ(world.layout_stamp<Position>(), position);
  EXPECT_NE(world.layout_stamp<Velocity>(), velocity);

  world.remove<Position>(entities[1]);
  const uint64_t removed = world.layout_stamp<Position>();
  EXPECT_NE(removed, position);
  world.add<Position>(entities[1]);  // the same entities again, in another order
  EXPECT_NE(world.layout_stamp<Position>(), removed);
  EXPECT_NE(world.layout_stamp<Position>(), position);

  World other;  // no pool of another world shares a stamp
  other.add<Position>(other.create());
  EXPECT_NE(other.layout_stamp<Position>(), position);
  EXPECT_NE(other.layout_stamp<Position>(), world.layout_stamp<Position>());
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

// Past 2 MiB an array lives in a huge-page mapping of its own (ecs/large_array.h): growing,
// compacting and freeing such arrays must keep every component.
TEST(World, PoolsLargerThanAHugePageKeepTheirComponents) {
  World world;
  constexpr std::uint32_t count = 300'000;  // dense entities 2.4 MB, sparse indices 1.2 MB
  const std::vector<Entity> created = world.create_many(count, Position{});
  for (std::uint32_t i = 0; i < count; ++i) world.add<Velocity>(created[i], Velocity{float(i), 0.0f});
  std::vector<Entity> odd;
  for (std::uint32_t i = 1; i < count; i += 2) odd.push_back(created[i]);
  EXPECT_EQ(world.destroy_many(odd), count / 2);
  std::uint32_t visited = 0;
  bool all_even = true;
  world.query<const Position, const Velocity>().for_each([&](Entity entity, const Position&,
                                                             const Velocity& velocity) {
    ++visited;
    all_even = all_even && static_cast<std::uint32_t>(velocity.x) == entity.index && entity.index % 2 == 0;
  });
  EXPECT_EQ(visited, count / 2);
  EXPECT_TRUE(all_even);
}

TEST(World, CreateManyGivesEveryEntityTheComponentsAndReusesFreedSlots) {
  World world;
  const Entity freed = world.create();
  world.destroy(freed);
  const Tick before = world.tick();
  world.advance_tick();
  const std::vector<Entity> created = world.create_many(1000, Position{1.0f, 2.0f}, Velocity{3.0f, 4.0f});
  ASSERT_EQ(created.size(), 1000u);
  EXPECT_EQ(created.front().index, freed.index);
  EXPECT_NE(created.front(), freed);
  EXPECT_EQ(world.entity_count(), 1000u);
  std::vector<Entity> visited;
  world.query<const Position, const Velocity>().changed_since<Position>(before).for_each(
      [&](Entity entity, const Position& position, const Velocity& velocity) {
        EXPECT_EQ(position.y, 2.0f);
        EXPECT_EQ(velocity.x, 3.0f);
        visited.push_back(entity);
      });
  std::sort(visited.begin(), visited.end(), [](Entity a, Entity b) { return a.index < b.index; });
  EXPECT_EQ(visited, created);
  // Single creation afterwards continues after the bulk.
  const Entity next = test::spawn_still(world);
  EXPECT_TRUE(world.alive(next));
  EXPECT_EQ(std::count(created.begin(), created.end(), next), 0);
}

TEST(World, DestroyManySkipsStaleAndRepeatedHandlesAndRecordsRemovals) {
  World world;
  world.keep_removals<Position, Velocity>();
  const std::vector<Entity> created = world.create_many(10, Position{});
  const Entity stale = world.create();
  world.destroy(stale);
  world.add<Velocity>(created[3]);
  const Tick before = world.tick();
  world.advance_tick();
  const std::vector<Entity> doomed{created[3], created[5], created[3], stale};
  EXPECT_EQ(world.destroy_many(doomed), 2u);
  EXPECT_FALSE(world.alive(created[3]));
  EXPECT_FALSE(world.alive(created[5]));
  EXPECT_EQ(world.entity_count(), 8u);
  EXPECT_EQ(world.query<const Position>().count(), 8u);
  EXPECT_EQ(world.removed_since<Position>(before).size(), 2u);
  ASSERT_EQ(world.removed_since<Velocity>(before).size(), 1u);
  EXPECT_EQ(world.removed_since<Velocity>(before)[0].entity, created[3]);
}

TEST(World, DestroyingMostEntitiesKeepsTheOthersComponentsAndChangeTicks) {
  World world;
  const std::vector<Entity> created = world.create_many(100, Position{}, Velocity{});
  for (const Entity entity : created) world.get_mut<Position>(entity).x = static_cast<float>(entity.index);
  const Tick before = world.tick();
  world.advance_tick();
  // Only late entities are written, and every early one is destroyed, so the written ones move
  // to slots whose neighbours were not written: their change must still be found.
  const std::vector<Entity> written{created[70], created[90]};
  for (const Entity entity : written) world.get_mut<Position>(entity);
  const std::vector<Entity> doomed(created.begin(), created.begin() + 64);
  EXPECT_EQ(world.destroy_many(doomed), doomed.size());
  std::size_t survivors = 0;
  world.query<const Position, const Velocity>().for_each(
      [&](Entity entity, const Position& position, const Velocity&) {
        EXPECT_EQ(position.x, static_cast<float>(entity.index));
        ++survivors;
      });
  std::vector<Entity> changed;
  world.query<const Position>().changed_since<Position>(before).for_each(
      [&](Entity entity, const Position&) { changed.push_back(entity); });
  EXPECT_EQ(survivors, created.size() - doomed.size());
  EXPECT_EQ(changed, written);
}

}  // namespace
}  // namespace sg::ecs
