// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ecs/entity.h"
#include "ecs/world.h"

namespace sg::ecs {

// Present on every entity that has a parent. Maintained by the functions below; do not add or
// edit it directly. Depth lets systems order work parents-first without walking up the tree.
struct Parent {
  Entity entity;
  std::uint32_t depth = 1;  // a root is at depth 0 and has no Parent
};

// Present on every entity that has (or had) children.
struct Children {
  std::vector<Entity> entities;
};

// Makes `child` a child of `parent`, detaching it from its previous parent. Marks the Parent
// component of `child` and of all its descendants changed (their depths and world matrices
// change). The world keeps Parent removals from then on (World::keep_removals). Throws
// std::invalid_argument for stale handles, `child == parent`, or when `parent` is a descendant of
// `child` (a cycle).
void set_parent(World& world, Entity child, Entity parent);

// Makes `child` a root. Its Parent removal is recorded, and its descendants' Parent components
// are marked changed. Does nothing if `child` has no parent.
void clear_parent(World& world, Entity child);

// The parent, or null_entity for a root.
Entity parent_of(const World& world, Entity entity);
std::span<const Entity> children_of(const World& world, Entity entity);
bool is_descendant(const World& world, Entity entity, Entity ancestor);

// Destroys the entity and all of its descendants, detaching it from its parent first.
void destroy_subtree(World& world, Entity root);

}  // namespace sg::ecs
