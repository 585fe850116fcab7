// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "ecs/query.h"
#include "ecs/world.h"
#include "test_components.h"

namespace sg::ecs {
namespace {

using test::Frozen;
using test::Position;
using test::Velocity;

struct Mass {
  float value = 0.0f;
};

// Adds, removes, creates and destroys at random, one by one and in bulk, the same way for the
// same seed; every component holds its entity's index, so a value that moved to another entity's
// slot shows.
void churn(World& world, std::vector<Entity>& entities, unsigned seed, int steps) {
  std::mt19937 random(seed);
  if (entities.empty()) entities.push_back(world.create());
  const auto pick = [&] {
    return entities[std::uniform_int_distribution<std::size_t>(0, entities.size() - 1)(random)];
  };
  for (int step = 0; step < steps; ++step) {
    const auto value = [](Entity entity) { return static_cast<float>(entity.index); };
    switch (random() % 8) {
      case 0: entities.push_back(world.create()); break;
      case 1: {
        const std::vector<Entity> created = world.create_many(5, Position{}, Velocity{});
        for (const Entity entity : created) {
          world.get_mut<Position>(entity).x = value(entity);
          world.get_mut<Velocity>(entity).x = value(entity);
        }
        entities.insert(entities.end(), created.begin(), created.end());
        break;
      }
      case 2:
      case 3:
        if (const Entity e = pick(); world.alive(e)) world.add<Position>(e, value(e), 0.0f);
        break;
      case 4:
        if (const Entity e = pick(); world.alive(e)) world.add<Velocity>(e, value(e), 0.0f);
        break;
      case 5: world.remove<Position>(pick()); break;
      case 6: world.remove<Velocity>(pick()); break;
      case 7: {
        if (random() % 4 == 0) {
          std::vector<Entity> doomed;
          for (int i = 0; i < 20; ++i) doomed.push_back(pick());
          world.destroy_many(doomed);
        } else {
          world.destroy(pick());
        }
        break;
      }
    }
  }
}

void expect_group_holds(const World& world, const OwningGroup& group) {
  for (const SparseSet* pool : group.pools()) {
    ASSERT_LE(group.size(), pool->size());
    for (std::uint32_t slot = 0; slot < pool->size(); ++slot) {
      const Entity entity = pool->entities()[slot];
      const bool member = world.has<Position>(entity) && world.has<Velocity>(entity);
      // Members first, in the same order in every owned pool; nobody else in front.
      ASSERT_EQ(slot < group.size(), member) << "slot " << slot;
      if (member) {
        ASSERT_EQ(group.pools().front()->entities()[slot], entity);
      }
    }
  }
  world.query<const Position>().for_each([](Entity entity, const Position& position) {
    ASSERT_EQ(position.x, static_cast<float>(entity.index));
  });
  world.query<const Velocity>().for_each([](Entity entity, const Velocity& velocity) {
    ASSERT_EQ(velocity.x, static_cast<float>(entity.index));
  });
}

TEST(OwningGroup, KeepsItsMembersInFrontOfEveryOwnedPoolThroughAddsRemovesAndDestroys) {
  World world;
  std::vector<Entity> entities;
  churn(world, entities, 1, 300);  // members from before the group is declared are gathered
  const OwningGroup& group = world.group<Position, Velocity>();
  expect_group_holds(world, group);
  for (unsigned round = 0; round < 20; ++round) {
    churn(world, entities, 100 + round, 100);
    expect_group_holds(world, group);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(group.size(), 0u);
}

std::vector<Entity> visited_by(World& world, bool exclude_frozen) {
  std::vector<Entity> visited;
  auto query = world.query<Position, const Velocity>();
  if (exclude_frozen) query.without<Frozen>();
  query.for_each([&](Entity entity, Position& position, const Velocity& velocity) {
    visited.push_back(entity);
    position.y += velocity.x;
  });
  std::sort(visited.begin(), visited.end(), [](Entity a, Entity b) { return a.index < b.index; });
  return visited;
}

std::vector<std::uint32_t> changed_positions(World& world, Tick since) {
  std::vector<std::uint32_t> changed;
  world.query<const Position>().changed_since<Position>(since).for_each(
      [&](Entity entity, const Position&) { changed.push_back(entity.index); });
  std::sort(changed.begin(), changed.end());
  return changed;
}

TEST(OwningGroup, QueriesVisitAndMarkTheSameEntitiesWithOrWithoutTheGroup) {
  World grouped;
  World plain;
  grouped.group<Position, Velocity>();
  std::vector<Entity> grouped_entities;
  std::vector<Entity> plain_entities;
  churn(grouped, grouped_entities, 7, 2000);
  churn(plain, plain_entities, 7, 2000);
  ASSERT_EQ(grouped_entities, plain_entities);
  for (std::size_t i = 0; i < plain_entities.size(); i += 3) {
    if (plain.alive(plain_entities[i])) {
      plain.add<Frozen>(plain_entities[i]);
      grouped.add<Frozen>(grouped_entities[i]);
    }
  }
  for (const bool exclude_frozen : {false, true}) {
    const Tick since = grouped.tick();
    grouped.advance_tick();
    plain.advance_tick();
    const std::vector<Entity> visited = visited_by(grouped, exclude_frozen);
    EXPECT_FALSE(visited.empty());
    EXPECT_EQ(visited, visited_by(plain, exclude_frozen));
    EXPECT_EQ(changed_positions(grouped, since), changed_positions(plain, since));
  }
  for (const Entity entity : plain_entities) {
    if (plain.has<Position>(entity)) {
      EXPECT_EQ(grouped.get<Position>(entity).y, plain.get<Position>(entity).y);
    }
  }
}

TEST(OwningGroup, AQueryWithMoreComponentsThanTheGroupLooksUpOnlyTheOthers) {
  World world;
  world.group<Position, Velocity>();
  std::vector<Entity> with_mass;
  for (int i = 0; i < 50; ++i) {
    const Entity entity = world.create();
    world.add<Position>(entity, static_cast<float>(i), 0.0f);
    if (i % 2 == 0) world.add<Velocity>(entity, 1.0f, 0.0f);
    if (i % 3 == 0) {
      world.add<Mass>(entity, 2.0f);
      if (i % 2 == 0) with_mass.push_back(entity);
    }
  }
  std::vector<Entity> visited;
  world.query<const Position, const Velocity, const Mass>().for_each(
      [&](Entity entity, const Position&, const Velocity&, const Mass&) { visited.push_back(entity); });
  std::sort(visited.begin(), visited.end(), [](Entity a, Entity b) { return a.index < b.index; });
  EXPECT_EQ(visited, with_mass);
}

TEST(OwningGroup, ParallelQueriesOverTheGroupMarkEveryVisitedComponent) {
  World world;
  const OwningGroup& group = world.group<Position, Velocity>();
  for (int i = 0; i < 10'000; ++i) {
    const Entity entity = world.create();
    world.add<Position>(entity);
    if (i % 7 != 0) world.add<Velocity>(entity, 1.0f, 0.0f);
  }
  const Tick since = world.tick();
  world.advance_tick();
  jobs::ThreadPool threads(3);
  world.query<Position, const Velocity>().for_each_parallel(
      threads, [](Position& position, const Velocity& velocity) { position.x += velocity.x; }, 100);
  std::size_t changed = 0;
  world.query<const Position>().changed_since<Position>(since).for_each([&](const Position& position) {
    EXPECT_EQ(position.x, 1.0f);
    ++changed;
  });
  EXPECT_EQ(changed, group.size());
  EXPECT_EQ(changed, 10'000u - 10'000u / 7 - 1);
}

TEST(OwningGroup, ASetIsDeclaredOnceAndAPoolBelongsToOneGroup) {
  World world;
  const OwningGroup& group = world.group<Position, Velocity>();
  EXPECT_EQ((&world.group<Velocity, Position>()), &group);
  EXPECT_THROW((world.group<Position, Mass>()), std::logic_error);
  EXPECT_THROW((world.group<Position, Velocity, Mass>()), std::logic_error);
}

}  // namespace
}  // namespace sg::ecs
