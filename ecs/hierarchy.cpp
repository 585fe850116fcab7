// SPDX-License-Identifier: MIT
#include "ecs/hierarchy.h"

#include <algorithm>
#include <stdexcept>

namespace sg::ecs {

namespace {

std::uint32_t depth_of(const World& world, Entity entity) {
  const Parent* parent = world.try_get<Parent>(entity);
  return parent == nullptr ? 0 : parent->depth;
}

void detach_from_parent(World& world, Entity child, Entity parent) {
  if (!world.has<Children>(parent)) return;
  std::vector<Entity>& siblings = world.get_mut<Children>(parent).entities;
  siblings.erase(std::remove(siblings.begin(), siblings.end(), child), siblings.end());
}

// Depth-first, children after their parent; `visit` may not restructure the hierarchy.
template <typename Visit>
void for_each_descendant(const World& world, Entity root, Visit visit) {
  const std::span<const Entity> roots_children = children_of(world, root);
  std::vector<Entity> pending(roots_children.begin(), roots_children.end());
  while (!pending.empty()) {
    const Entity entity = pending.back();
    pending.pop_back();
    visit(entity);
    const std::span<const Entity> children = children_of(world, entity);
    pending.insert(pending.end(), children.begin(), children.end());
  }
}

void update_descendant_depths(World& world, Entity root) {
  for_each_descendant(world, root, [&](Entity descendant) {
    const Entity parent = world.get<Parent>(descendant).entity;
    world.get_mut<Parent>(descendant).depth = depth_of(world, parent) + 1;
  });
}

}  // namespace

void set_parent(World& world, Entity child, Entity parent) {
  if (!world.alive(child) || !world.alive(parent)) {
    throw std::invalid_argument("sg::ecs::set_parent: stale entity handle");
  }
  if (child == parent || is_descendant(world, parent, child)) {
    throw std::invalid_argument("sg::ecs::set_parent: would create a cycle");
  }
  const Entity old_parent = parent_of(world, child);
  if (old_parent != null_entity) detach_from_parent(world, child, old_parent);
  world.keep_removals<Parent>();  // update_world_transforms reads them: an entity became a root
  world.add<Parent>(child, Parent{parent, depth_of(world, parent) + 1});
  if (!world.has<Children>(parent)) world.add<Children>(parent);
  world.get_mut<Children>(parent).entities.push_back(child);
  update_descendant_depths(world, child);
}

void clear_parent(World& world, Entity child) {
  const Entity parent = parent_of(world, child);
  if (parent == null_entity) return;
  detach_from_parent(world, child, parent);
  world.remove<Parent>(child);
  update_descendant_depths(world, child);
}

Entity parent_of(const World& world, Entity entity) {
  const Parent* parent = world.try_get<Parent>(entity);
  return parent == nullptr ? null_entity : parent->entity;
}

std::span<const Entity> children_of(const World& world, Entity entity) {
  const Children* children = world.try_get<Children>(entity);
  return children == nullptr ? std::span<const Entity>{} : children->entities;
}

bool is_descendant(const World& world, Entity entity, Entity ancestor) {
  for (Entity up = parent_of(world, entity); up != null_entity; up = parent_of(world, up)) {
    if (up == ancestor) return true;
  }
  return false;
}

void destroy_subtree(World& world, Entity root) {
  clear_parent(world, root);
  std::vector<Entity> doomed{root};
  for_each_descendant(world, root, [&](Entity descendant) { doomed.push_back(descendant); });
  for (const Entity entity : doomed) world.destroy(entity);
}

}  // namespace sg::ecs
