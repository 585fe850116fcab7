// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "ecs/hierarchy.h"

namespace sg::ecs {
namespace {

TEST(Hierarchy, SetParentLinksBothWays) {
  World world;
  const Entity parent = world.create();
  const Entity child = world.create();
  set_parent(world, child, parent);
  EXPECT_EQ(parent_of(world, child), parent);
  EXPECT_EQ(parent_of(world, parent), null_entity);
  ASSERT_EQ(children_of(world, parent).size(), 1u);
  EXPECT_EQ(children_of(world, parent)[0], child);
  EXPECT_EQ(world.get<Parent>(child).depth, 1u);
}

TEST(Hierarchy, ReparentingMovesChildAndUpdatesDepths) {
  World world;
  const Entity a = world.create();
  const Entity b = world.create();
  const Entity b_child = world.create();
  const Entity child = world.create();
  const Entity grandchild = world.create();
  set_parent(world, b_child, b);
  set_parent(world, child, a);
  set_parent(world, grandchild, child);
  EXPECT_EQ(world.get<Parent>(grandchild).depth, 2u);

  set_parent(world, child, b_child);
  EXPECT_TRUE(children_of(world, a).empty());
  EXPECT_EQ(parent_of(world, child), b_child);
  EXPECT_EQ(world.get<Parent>(child).depth, 2u);
  EXPECT_EQ(world.get<Parent>(grandchild).depth, 3u);
  EXPECT_TRUE(is_descendant(world, grandchild, b));
  EXPECT_FALSE(is_descendant(world, grandchild, a));
}

TEST(Hierarchy, RejectsCyclesAndStaleHandles) {
  World world;
  const Entity root = world.create();
  const Entity child = world.create();
  set_parent(world, child, root);
  EXPECT_THROW(set_parent(world, root, child), std::invalid_argument);
  EXPECT_THROW(set_parent(world, root, root), std::invalid_argument);
  const Entity dead = world.create();
  world.destroy(dead);
  EXPECT_THROW(set_parent(world, child, dead), std::invalid_argument);
  EXPECT_EQ(parent_of(world, child), root);
}

TEST(Hierarchy, ClearParentMakesRootAndRecordsRemoval) {
  World world;
  world.keep_removals<Parent>();
  const Entity parent = world.create();
  const Entity child = world.create();
  const Entity grandchild = world.create();
  set_parent(world, child, parent);
  set_parent(world, grandchild, child);
  const Tick before = world.tick();
  world.advance_tick();
  clear_parent(world, child);
  EXPECT_EQ(parent_of(world, child), null_entity);
  EXPECT_TRUE(children_of(world, parent).empty());
  EXPECT_EQ(world.get<Parent>(grandchild).depth, 1u);
  ASSERT_EQ(world.removed_since<Parent>(before).size(), 1u);
  EXPECT_EQ(world.removed_since<Parent>(before)[0].entity, child);
}

TEST(Hierarchy, DestroySubtreeDestroysDescendantsOnly) {
  World world;
  const Entity root = world.create();
  const Entity branch = world.create();
  const Entity leaf = world.create();
  const Entity sibling = world.create();
  set_parent(world, branch, root);
  set_parent(world, leaf, branch);
  set_parent(world, sibling, root);
  destroy_subtree(world, branch);
  EXPECT_FALSE(world.alive(branch));
  EXPECT_FALSE(world.alive(leaf));
  EXPECT_TRUE(world.alive(sibling));
  EXPECT_EQ(children_of(world, root).size(), 1u);
}

}  // namespace
}  // namespace sg::ecs
