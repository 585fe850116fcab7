// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <vector>

#include "ecs/query.h"
#include "ecs/world.h"
#include "test_components.h"

namespace sg::ecs {
namespace {

using test::Frozen;
using test::Position;
using test::Velocity;

// Enough entities for several parallel tasks per query.
constexpr int entity_count = 100'000;

std::vector<Entity> sorted(std::vector<Entity> entities) {
  std::sort(entities.begin(), entities.end(), [](Entity a, Entity b) { return a.index < b.index; });
  return entities;
}

// Every entity has a Position, every third a Velocity (so pools are not aligned), every
// seventh is Frozen.
World make_world() {
  World world;
  for (int i = 0; i < entity_count; ++i) {
    const Entity entity = world.create();
    world.add<Position>(entity, static_cast<float>(i), 0.0f);
    if (i % 3 == 0) world.add<Velocity>(entity, 1.0f, 2.0f);
    if (i % 7 == 0) world.add<Frozen>(entity);
  }
  return world;
}

template <typename Query>
std::vector<Entity> visit_serially(Query query) {
  std::vector<Entity> visited;
  query.for_each([&](Entity entity, auto&...) { visited.push_back(entity); });
  return visited;
}

template <typename Query>
std::vector<Entity> visit_in_parallel(Query query, jobs::ThreadPool& threads, std::size_t entities_per_task) {
  std::mutex mutex;
  std::vector<Entity> visited;
  query.for_each_parallel(
      threads,
      [&](Entity entity, auto&...) {
        const std::lock_guard lock(mutex);
        visited.push_back(entity);
      },
      entities_per_task);
  return visited;
}

TEST(ParallelQuery, VisitsTheSameEntitiesAsSerialIteration) {
  World world = make_world();
  jobs::ThreadPool threads(3);
  // The default tasks, and small uneven ones (many tasks, the last one short).
  const auto check = [&](auto query) {
    const std::vector<Entity> serial = visit_serially(query);
    EXPECT_GT(serial.size(), 0u);
    for (const std::size_t per_task : {std::size_t{16384}, std::size_t{1000}, std::size_t{7}}) {
      EXPECT_EQ(sorted(serial), sorted(visit_in_parallel(query, threads, per_task))) << per_task;
    }
  };
  check(world.query<const Position>());                    // every slot
  check(world.query<const Position, const Velocity>());    // sparse lookups
  check(world.query<const Position>().without<Frozen>());  // exclusion
  const Tick before = world.tick();
  world.advance_tick();
  for (int i = 0; i < entity_count; i += 5) world.get_mut<Position>(Entity{static_cast<std::uint32_t>(i), 0});
  check(world.query<const Position>().changed_since<Position>(before));  // change history
  const World& reader = world;
  check(reader.query<const Position, const Velocity>());
}

TEST(ParallelQuery, WritesAndChangeMarksMatchSerialIteration) {
  World serial_world = make_world();
  World parallel_world = make_world();
  jobs::ThreadPool threads(3);
  const auto move = [](Position& position, const Velocity& velocity) {
    position.x += velocity.x;
    position.y += velocity.y;
  };
  const Tick before = serial_world.tick();
  serial_world.advance_tick();
  parallel_world.advance_tick();
  serial_world.query<Position, const Velocity>().for_each(move);
  parallel_world.query<Position, const Velocity>().for_each_parallel(threads, move, 1000);
  for (std::uint32_t i = 0; i < entity_count; ++i) {
    const Entity entity{i, 0};
    ASSERT_EQ(serial_world.get<Position>(entity).x, parallel_world.get<Position>(entity).x);
    ASSERT_EQ(serial_world.change_tick<Position>(entity), parallel_world.change_tick<Position>(entity));
  }
  EXPECT_EQ(visit_serially(parallel_world.query<const Position>().changed_since<Position>(before)).size(),
            static_cast<std::size_t>((entity_count + 2) / 3));
}

}  // namespace
}  // namespace sg::ecs
