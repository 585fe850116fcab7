// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "ecs/query.h"
#include "ecs/world.h"
#include "test_components.h"

namespace sg::ecs {
namespace {

using test::Frozen;
using test::Position;
using test::Velocity;

TEST(Query, VisitsOnlyEntitiesWithAllComponents) {
  World world;
  const Entity moving = test::spawn_moving(world, {1.0f, 2.0f});
  const Entity still = test::spawn_still(world);
  const Entity ghost = world.create();
  world.add<Velocity>(ghost);

  std::vector<Entity> visited;
  world.query<Position, const Velocity>().for_each(
      [&](Entity entity, Position& position, const Velocity& velocity) {
        visited.push_back(entity);
        position.x += velocity.x;
        position.y += velocity.y;
      });
  EXPECT_EQ(visited, std::vector<Entity>{moving});
  EXPECT_EQ(world.get<Position>(moving).y, 2.0f);
  EXPECT_EQ(world.get<Position>(still).y, 0.0f);
}

TEST(Query, WorksWhenPoolsHaveDifferentOrders) {
  World world;
  std::vector<Entity> entities;
  for (int i = 0; i < 6; ++i) entities.push_back(world.create());
  // Velocity added in reverse order, so slot hints miss and lookups must go through sparse.
  for (int i = 0; i < 6; ++i) world.add<Position>(entities[i], static_cast<float>(i), 0.0f);
  for (int i = 5; i >= 0; --i) world.add<Velocity>(entities[i], 10.0f, 0.0f);
  world.query<Position, const Velocity>().for_each(
      [](Position& position, const Velocity& velocity) { position.x += velocity.x; });
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(world.get<Position>(entities[i]).x, 10.0f + static_cast<float>(i));
  }
}

TEST(Query, ExcludesEntitiesWithExcludedComponent) {
  World world;
  const Entity frozen = test::spawn_still(world);
  world.add<Frozen>(frozen);
  const Entity free = test::spawn_still(world);

  std::vector<Entity> visited;
  world.query<const Position>().without<Frozen>().for_each(
      [&](Entity entity, const Position&) { visited.push_back(entity); });
  EXPECT_EQ(visited, std::vector<Entity>{free});
}

TEST(Query, CountOfEmptyWorldIsZero) {
  World world;
  EXPECT_EQ((world.query<const Position, const Velocity>().count()), 0u);
}

TEST(Query, ReadOnlyAccessDoesNotMarkChanged) {
  World world;
  const Entity entity = test::spawn_moving(world);
  const Tick added = world.tick();
  world.advance_tick();
  world.query<Position, const Velocity>().for_each([](Position&, const Velocity&) {});
  EXPECT_EQ(world.change_tick<Velocity>(entity), added);
  EXPECT_EQ(world.change_tick<Position>(entity), world.tick());
}

TEST(Query, StaysCorrectWhenAlignedPoolsLoseTheirAlignment) {
  World world;
  std::vector<Entity> entities;
  for (int i = 0; i < 4; ++i) {
    entities.push_back(world.create());
    world.add<Position>(entities.back(), static_cast<float>(i), 0.0f);
    world.add<Velocity>(entities.back(), 1.0f, 0.0f);
  }
  const auto step = [&] {
    world.query<Position, const Velocity>().for_each(
        [](Position& position, const Velocity& velocity) { position.x += velocity.x; });
  };
  step();  // aligned: same entities in the same slots
  world.remove<Velocity>(entities[0]);
  world.add<Velocity>(entities[0], 100.0f, 0.0f);  // same sizes, different order
  step();
  EXPECT_EQ(world.get<Position>(entities[0]).x, 101.0f);
  EXPECT_EQ(world.get<Position>(entities[3]).x, 5.0f);
}

TEST(Query, ExclusionAppliesToAlignedPools) {
  World world;
  test::spawn_still(world);
  world.add<Frozen>(test::spawn_still(world));
  EXPECT_EQ(world.query<const Position>().without<Frozen>().count(), 1u);
}

TEST(Query, AConstWorldGivesReadOnlyQueries) {
  World world;
  const Entity moving = test::spawn_moving(world, {1.0f, 0.0f});
  world.add<Frozen>(test::spawn_moving(world));
  const Tick before = world.tick();
  world.advance_tick();

  const World& reader = world;
  std::vector<Entity> visited;
  reader.query<const Position, const Velocity>().without<Frozen>().for_each(
      [&](Entity entity, const Position&, const Velocity&) { visited.push_back(entity); });
  EXPECT_EQ(visited, std::vector<Entity>{moving});
  // Reading marks nothing changed.
  EXPECT_EQ(reader.query<const Position>().changed_since<const Position>(before).count(), 0u);
}

TEST(Query, AConstQueryOfAnUnknownComponentVisitsNothing) {
  struct NeverAdded {};
  World world;
  test::spawn_still(world);
  const World& reader = world;
  EXPECT_EQ((reader.query<const Position, const NeverAdded>().count()), 0u);
  EXPECT_EQ(reader.query<const Position>().without<NeverAdded>().count(), 1u);
}

TEST(Query, AReusedIndexDoesNotInheritTheDestroyedEntitysComponents) {
  World world;
  const Entity old = test::spawn_moving(world);
  test::spawn_moving(world);  // moves into old's Velocity slot when old is destroyed
  // More Velocities than Positions, so the query walks Positions and looks Velocities up.
  for (int i = 0; i < 3; ++i) world.add<Velocity>(world.create());
  world.destroy(old);
  const Entity reused = world.create();
  ASSERT_EQ(reused.index, old.index);
  world.add<Position>(reused);
  std::vector<Entity> visited;
  world.query<const Position, const Velocity>().for_each(
      [&](Entity entity, const Position&, const Velocity&) { visited.push_back(entity); });
  EXPECT_EQ(std::count(visited.begin(), visited.end(), reused), 0);
  EXPECT_EQ(visited.size(), 1u);
  EXPECT_FALSE(world.has<Velocity>(reused));
}

// Velocity added in reverse creation order: both pools hold the same entities in other orders.
std::vector<Entity> spawn_in_two_orders(World& world, int count) {
  std::vector<Entity> entities;
  for (int i = 0; i < count; ++i) entities.push_back(world.create());
  for (int i = 0; i < count; ++i) world.add<Position>(entities[i], static_cast<float>(i), 0.0f);
  for (int i = count - 1; i >= 0; --i) world.add<Velocity>(entities[i], static_cast<float>(10 * i), 0.0f);
  return entities;
}

std::vector<Entity> velocity_order(World& world) {
  std::vector<Entity> order;
  world.query<const Velocity>().for_each([&](Entity entity, const Velocity&) { order.push_back(entity); });
  return order;
}

TEST(Query, PoolsOfOneSetOfEntitiesInOtherOrdersTakeEntityOrderAtTheNextTick) {
  World world;
  const std::vector<Entity> entities = spawn_in_two_orders(world, 40);
  const std::vector<Entity> reversed(entities.rbegin(), entities.rend());
  const Tick added = world.tick();
  world.advance_tick();
  world.get_mut<Velocity>(entities[7]).y = 1.0f;  // one newer change tick, which must follow its entity
  const Tick written = world.tick();

  const auto step = [&] {
    world.query<Position, const Velocity>().for_each(
        [](Position& position, const Velocity& velocity) { position.x += velocity.x; });
  };
  step();
  EXPECT_EQ(velocity_order(world), reversed) << "a query reorders nothing while it runs";
  world.advance_tick();
  EXPECT_EQ(velocity_order(world), entities);
  step();
  for (int i = 0; i < 40; ++i) {
    EXPECT_EQ(world.get<Position>(entities[i]).x, static_cast<float>(i + 2 * 10 * i));
    EXPECT_EQ(world.change_tick<Velocity>(entities[i]), i == 7 ? written : added);
  }
  std::vector<Entity> changed;
  world.query<const Velocity>().changed_since<const Velocity>(added).for_each(
      [&](Entity entity, const Velocity&) { changed.push_back(entity); });
  EXPECT_EQ(changed, std::vector<Entity>{entities[7]});
}

TEST(Query, ANestedQueryOverPoolsInOtherOrdersSeesEveryEntity) {
  World world;
  const std::vector<Entity> entities = spawn_in_two_orders(world, 8);
  std::size_t pairs = 0;
  world.query<Position, const Velocity>().for_each(
      [&](Position&, const Velocity&) { pairs += world.query<const Position, const Velocity>().count(); });
  EXPECT_EQ(pairs, entities.size() * entities.size());
}

TEST(Query, PoolsOfDifferentSizesOrOfAGroupKeepTheirOrder) {
  World unequal;
  const std::vector<Entity> entities = spawn_in_two_orders(unequal, 8);
  unequal.add<Position>(unequal.create());
  unequal.query<Position, const Velocity>().for_each([](Position&, const Velocity&) {});
  unequal.advance_tick();
  EXPECT_EQ(velocity_order(unequal), std::vector<Entity>(entities.rbegin(), entities.rend()));

  // Frozen added to the group's members in reverse: Position's order is the group's to keep.
  World grouped;
  grouped.group<Position, Velocity>();
  const std::vector<Entity> members = spawn_in_two_orders(grouped, 8);
  for (auto member = members.rbegin(); member != members.rend(); ++member) grouped.add<Frozen>(*member);
  const auto position_order = [&] {
    std::vector<Entity> order;
    grouped.query<const Position>().for_each(
        [&](Entity entity, const Position&) { order.push_back(entity); });
    return order;
  };
  const std::vector<Entity> group_order = position_order();
  grouped.query<Position, const Frozen>().for_each([](Position&, const Frozen&) {});
  grouped.advance_tick();
  EXPECT_EQ(position_order(), group_order);
}

}  // namespace
}  // namespace sg::ecs
