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

using test::Position;
using test::Velocity;

std::vector<Entity> changed_positions(World& world, Tick since) {
  std::vector<Entity> changed;
  world.query<const Position>().changed_since<Position>(since).for_each(
      [&](Entity entity, const Position&) { changed.push_back(entity); });
  return changed;
}

std::vector<Entity> sorted(std::vector<Entity> entities) {
  std::sort(entities.begin(), entities.end(), [](Entity a, Entity b) { return a.index < b.index; });
  return entities;
}

TEST(ChangeDetection, AddMarksChangedAtCurrentTick) {
  World world;
  world.advance_tick();
  const Entity entity = test::spawn_still(world);
  EXPECT_EQ(world.change_tick<Position>(entity), world.tick());
  EXPECT_EQ(changed_positions(world, world.tick() - 1), std::vector<Entity>{entity});
  EXPECT_TRUE(changed_positions(world, world.tick()).empty());
}

TEST(ChangeDetection, TicksAcrossFrames) {
  World world;
  const Entity a = test::spawn_still(world);
  const Entity b = test::spawn_still(world);
  const Entity c = test::spawn_still(world);
  const Tick frame1 = world.tick();

  world.advance_tick();
  world.get_mut<Position>(b).x = 1.0f;
  const Tick frame2 = world.tick();

  world.advance_tick();
  world.get_mut<Position>(c).x = 1.0f;
  world.get_mut<Position>(c).y = 1.0f;  // a second write in a tick is reported once

  EXPECT_EQ(sorted(changed_positions(world, 0)), (std::vector<Entity>{a, b, c}));
  EXPECT_EQ(sorted(changed_positions(world, frame1)), (std::vector<Entity>{b, c}));
  EXPECT_EQ(changed_positions(world, frame2), std::vector<Entity>{c});
  EXPECT_TRUE(changed_positions(world, world.tick()).empty());
  EXPECT_EQ(world.change_tick<Position>(a), frame1);
  EXPECT_EQ(world.change_tick<Position>(b), frame2);
}

TEST(ChangeDetection, RewrittenEntityIsReportedOnceAtItsNewestTick) {
  World world;
  const Entity entity = test::spawn_still(world);
  const Tick added = world.tick();
  world.advance_tick();
  world.get_mut<Position>(entity);
  EXPECT_EQ(changed_positions(world, 0), std::vector<Entity>{entity});
  EXPECT_EQ(changed_positions(world, added), std::vector<Entity>{entity});
  EXPECT_EQ(world.change_tick<Position>(entity), added + 1);
}

TEST(ChangeDetection, MutableQueryMarksEveryVisitedEntity) {
  World world;
  const Entity moving = test::spawn_moving(world);
  test::spawn_still(world);
  const Tick before = world.tick();
  world.advance_tick();
  world.query<Position, const Velocity>().for_each([](Position&, const Velocity&) {});
  EXPECT_EQ(changed_positions(world, before), std::vector<Entity>{moving});
}

TEST(ChangeDetection, ChangedQueryCombinesWithOtherComponents) {
  World world;
  const Entity with_velocity = test::spawn_moving(world, {3.0f, 0.0f});
  const Entity without_velocity = test::spawn_still(world);
  const Tick before = world.tick();
  world.advance_tick();
  world.get_mut<Position>(with_velocity);
  world.get_mut<Position>(without_velocity);

  std::vector<float> velocities;
  world.query<const Position, const Velocity>().changed_since<Position>(before).for_each(
      [&](const Position&, const Velocity& velocity) { velocities.push_back(velocity.x); });
  EXPECT_EQ(velocities, std::vector<float>{3.0f});
}

TEST(ChangeDetection, RemovedComponentIsNotReportedChanged) {
  World world;
  const Entity entity = test::spawn_still(world);
  world.remove<Position>(entity);
  EXPECT_TRUE(changed_positions(world, 0).empty());
}

TEST(ChangeDetection, ReAddedInSameTickIsReportedOnce) {
  World world;
  const Entity entity = test::spawn_still(world);
  world.remove<Position>(entity);
  world.add<Position>(entity);
  EXPECT_EQ(changed_positions(world, 0), std::vector<Entity>{entity});
}

TEST(ChangeDetection, RemovalsAndDestructionAreRecordedPerComponentType) {
  World world;
  world.keep_removals<Position, Velocity>();
  const Entity removed = test::spawn_moving(world);
  const Entity destroyed = test::spawn_moving(world);
  test::spawn_moving(world);
  const Tick before = world.tick();
  world.advance_tick();
  world.remove<Position>(removed);
  world.destroy(destroyed);

  const auto position_removals = world.removed_since<Position>(before);
  ASSERT_EQ(position_removals.size(), 2u);
  EXPECT_EQ(position_removals[0].entity, removed);
  EXPECT_EQ(position_removals[1].entity, destroyed);
  EXPECT_EQ(position_removals[1].tick, world.tick());
  const auto velocity_removals = world.removed_since<Velocity>(before);
  ASSERT_EQ(velocity_removals.size(), 1u);
  EXPECT_EQ(velocity_removals[0].entity, destroyed);
  EXPECT_TRUE(world.removed_since<Position>(world.tick()).empty());

  world.forget_removals_before(world.tick() + 1);
  EXPECT_TRUE(world.removed_since<Position>(0).empty());
}

TEST(ChangeDetection, RemovalsAreKeptOnlyForTypesThatAskAndReadingOthersThrows) {
  World world;
  world.keep_removals<Velocity>();
  const Entity first = test::spawn_moving(world);
  const Entity second = test::spawn_moving(world);
  const Tick before = world.tick();
  world.advance_tick();
  world.destroy(first);
  EXPECT_THROW((void)world.removed_since<Position>(before), std::logic_error);
  EXPECT_THROW((void)world.removed_since<test::Frozen>(before), std::logic_error);  // never used
  ASSERT_EQ(world.removed_since<Velocity>(before).size(), 1u);

  // Keeping starts when asked: later removals are recorded, earlier ones were not.
  world.keep_removals<Position>();
  world.destroy_many(std::vector<Entity>{second});
  ASSERT_EQ(world.removed_since<Position>(before).size(), 1u);
  EXPECT_EQ(world.removed_since<Position>(before)[0].entity, second);
  EXPECT_EQ(world.removed_since<Velocity>(before).size(), 2u);
}

TEST(ChangeDetection, HistoryStaysCorrectAcrossManyFramesOfFullRewrites) {
  // Enough frames for the change log to compact several times.
  World world;
  std::vector<Entity> entities;
  for (int i = 0; i < 3000; ++i) {
    entities.push_back(test::spawn_still(world));
  }
  Tick before_last_frame = 0;
  for (int frame = 0; frame < 10; ++frame) {
    before_last_frame = world.tick();
    world.advance_tick();
    world.query<Position>().for_each([](Position& position) { position.x += 1.0f; });
  }
  world.advance_tick();
  world.get_mut<Position>(entities[42]);
  EXPECT_EQ(changed_positions(world, before_last_frame).size(), entities.size());
  EXPECT_EQ(changed_positions(world, world.tick() - 1), std::vector<Entity>{entities[42]});
  EXPECT_EQ(world.change_tick<Position>(entities[7]), world.tick() - 1);
}

TEST(ChangeDetection, FullUpdateFollowedBySparseWritesAndAdds) {
  World world;
  std::vector<Entity> entities;
  for (int i = 0; i < 5; ++i) {
    entities.push_back(test::spawn_still(world));
  }
  const Tick before_full = world.tick();
  world.advance_tick();
  world.query<Position>().for_each([](Position& position) { position.x = 1.0f; });
  const Tick full = world.tick();
  world.get_mut<Position>(entities[1]);  // also written individually in the same tick
  world.advance_tick();
  world.get_mut<Position>(entities[3]);
  const Entity added = test::spawn_still(world);

  EXPECT_EQ(changed_positions(world, before_full).size(), 6u);
  EXPECT_EQ(sorted(changed_positions(world, full)), (std::vector<Entity>{entities[3], added}));
  EXPECT_EQ(world.change_tick<Position>(entities[0]), full);
  EXPECT_EQ(world.change_tick<Position>(entities[1]), full);
  EXPECT_EQ(world.change_tick<Position>(entities[3]), world.tick());
}

TEST(ChangeDetection, WritesInsideChangedQueryDoNotRepeatOrHideEntities) {
  World world;
  const Entity a = test::spawn_still(world);
  const Entity b = test::spawn_still(world);
  const Tick before = world.tick();
  world.advance_tick();
  world.get_mut<Position>(a);
  world.get_mut<Position>(b);
  world.advance_tick();

  int visits = 0;
  world.query<Position>().changed_since<Position>(before).for_each([&](Position& position) {
    ++visits;
    position.x += 1.0f;
    world.get_mut<Position>(b);
  });
  EXPECT_EQ(visits, 2);
}

// A changed-since query run inside another's callback lists its own changes: each query running
// borrows a slot list of its own from the world, over frames in which the lists are reused.
TEST(ChangeDetection, AChangedQueryInsideAnotherListsItsOwnChanges) {
  World world;
  std::vector<Entity> entities;
  for (int i = 0; i < 8; ++i) entities.push_back(test::spawn_moving(world));
  for (int frame = 0; frame < 3; ++frame) {
    const Tick before = world.tick();
    world.advance_tick();
    for (int i = 0; i < 8; ++i) {
      if (i % 2 == frame % 2) world.get_mut<Position>(entities[i]);
      if (i % 3 == frame % 3) world.get_mut<Velocity>(entities[i]);
    }
    std::vector<Entity> positions, velocities;
    world.query<const Position>().changed_since<Position>(before).for_each(
        [&](Entity entity, const Position&) {
          positions.push_back(entity);
          if (positions.size() > 1) return;
          world.query<const Velocity>().changed_since<Velocity>(before).for_each(
              [&](Entity moved, const Velocity&) { velocities.push_back(moved); });
        });
    std::vector<Entity> expected_positions, expected_velocities;
    for (int i = 0; i < 8; ++i) {
      if (i % 2 == frame % 2) expected_positions.push_back(entities[i]);
      if (i % 3 == frame % 3) expected_velocities.push_back(entities[i]);
    }
    EXPECT_EQ(sorted(positions), sorted(expected_positions)) << "frame " << frame;
    EXPECT_EQ(sorted(velocities), sorted(expected_velocities)) << "frame " << frame;
  }
}

TEST(ChangeDetection, PartialWritesOverManyTicksMatchAModel) {
  // Sparse writes, adds and removals over enough ticks for the change log to be compacted in
  // several passes, each spread over ticks; every tick the reported history is checked against
  // a plain table of last-write ticks, including readers looking far back (across a pass).
  World world;
  std::mt19937 random{7};
  std::vector<Entity> entities;
  std::vector<Tick> written;  // by entity index; 0 when the entity has no Position
  for (int i = 0; i < 4000; ++i) {
    entities.push_back(test::spawn_still(world));
    written.push_back(world.tick());
  }
  for (int frame = 0; frame < 120; ++frame) {
    world.advance_tick();
    for (int w = 0; w < 1500; ++w) {
      const std::size_t i = random() % entities.size();
      if (written[i] == 0) continue;
      world.get_mut<Position>(entities[i]);
      written[i] = world.tick();
    }
    const std::size_t toggled = random() % entities.size();
    if (written[toggled] == 0) {
      world.add<Position>(entities[toggled]);
      written[toggled] = world.tick();
    } else {
      world.remove<Position>(entities[toggled]);
      written[toggled] = 0;
    }
    for (const Tick since : {world.tick() - 1, world.tick() - 7, world.tick() / 2}) {
      std::vector<Entity> expected;
      for (std::size_t i = 0; i < entities.size(); ++i) {
        if (written[i] > since) expected.push_back(entities[i]);
      }
      ASSERT_EQ(sorted(changed_positions(world, since)), expected)
          << "frame " << frame << ", since " << since;
    }
    const std::size_t probe = random() % entities.size();
    if (written[probe] != 0) {
      ASSERT_EQ(world.change_tick<Position>(entities[probe]), written[probe]);
    }
  }
}

TEST(ChangeDetection, AChangeMovedByARemovalIsStillFound) {
  World world;
  std::vector<Entity> entities;
  for (int i = 0; i < 40; ++i) entities.push_back(test::spawn_still(world));
  const Tick before = world.tick();
  world.advance_tick();
  world.get_mut<Position>(entities.back());
  // Removing the first swaps the last, just written, into a slot whose neighbours were not.
  world.remove<Position>(entities.front());
  EXPECT_EQ(changed_positions(world, before), std::vector<Entity>{entities.back()});
}

}  // namespace
}  // namespace sg::ecs
