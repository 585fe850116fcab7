// SPDX-License-Identifier: MIT
#include "ecs/transform_system.h"

#include <algorithm>
#include <vector>

#include "ecs/hierarchy.h"
#include "ecs/query.h"
#include "ecs/transform.h"

namespace sg::ecs {

namespace {

struct DirtyRoot {
  std::uint32_t depth;
  Entity entity;
};

// Entities whose own world matrix is out of date: their local transform changed, or their place
// in the hierarchy did (new parent, new depth, or no parent any more).
std::vector<DirtyRoot> find_dirty(World& world, Tick since) {
  std::vector<Entity> changed;
  // Entities outside any hierarchy are done by update_world_transforms' own pass; the queries
  // look each change up in the hierarchy's pools directly (an entity with both is listed twice,
  // and visited once).
  world.query<const LocalTransform, const Parent>().changed_since<LocalTransform>(since).for_each(
      [&](Entity entity, const LocalTransform&, const Parent&) { changed.push_back(entity); });
  world.query<const LocalTransform, const Children>().changed_since<LocalTransform>(since).for_each(
      [&](Entity entity, const LocalTransform&, const Children&) { changed.push_back(entity); });
  world.query<const Parent>().changed_since<Parent>(since).for_each(
      [&](Entity entity, const Parent&) { changed.push_back(entity); });
  if (world.keeps_removals<Parent>()) {  // set_parent asks for them; no hierarchy, no removals
    for (const Removal& removal : world.removed_since<Parent>(since)) {
      if (world.alive(removal.entity)) changed.push_back(removal.entity);
    }
  }
  std::vector<DirtyRoot> dirty;
  dirty.reserve(changed.size());
  for (const Entity entity : changed) {
    const Parent* parent = world.try_get<Parent>(entity);
    dirty.push_back(DirtyRoot{parent == nullptr ? 0 : parent->depth, entity});
  }
  const auto shallower = [](const DirtyRoot& a, const DirtyRoot& b) { return a.depth < b.depth; };
  // Mostly roots (depth 0) moving, already in order.
  if (!std::is_sorted(dirty.begin(), dirty.end(), shallower))
    std::sort(dirty.begin(), dirty.end(), shallower);
  return dirty;
}

// The entities a frame's update has recomputed, by slot index: a flag per slot rather than a hash
// set, which cost more than the matrices themselves when thousands of entities move each frame.
class Visited {
 public:
  bool contains(Entity entity) const { return entity.index < seen_.size() && seen_[entity.index] != 0; }
  void insert(Entity entity) {
    if (entity.index >= seen_.size()) seen_.resize(std::size_t{entity.index} + entity.index / 2 + 64, 0);
    seen_[entity.index] = 1;
  }

 private:
  std::vector<std::uint8_t> seen_;
};

glm::mat4 parent_matrix(const World& world, Entity entity) {
  const WorldTransform* parent_world = world.try_get<WorldTransform>(parent_of(world, entity));
  return parent_world == nullptr ? glm::mat4{1.0f} : parent_world->matrix;
}

// Recomputes `root` and everything below it, recording what it visited in `updated`. `pending`
// is working storage, empty on entry and on return: one vector for a frame's thousands of
// subtrees, most of them a single entity.
void update_subtree(World& world, Entity root, Visited& updated, std::vector<Entity>& pending) {
  pending.push_back(root);
  while (!pending.empty()) {
    const Entity entity = pending.back();
    pending.pop_back();
    updated.insert(entity);
    const LocalTransform* local = world.try_get<LocalTransform>(entity);
    if (local != nullptr && world.has<WorldTransform>(entity)) {
      world.get_mut<WorldTransform>(entity).matrix = parent_matrix(world, entity) * to_matrix(*local);
    }
    const std::span<const Entity> children = children_of(world, entity);
    pending.insert(pending.end(), children.begin(), children.end());
  }
}

}  // namespace

void update_world_transforms(World& world, Tick since, jobs::ThreadPool* threads) {
  // Most moving things (crates, lights) have neither parent nor children: their world matrix is
  // their local one, with none of a subtree's lookups and in any order, so in parallel.
  world.query<const LocalTransform, WorldTransform>()
      .without<Parent, Children>()
      .changed_since<LocalTransform>(since)
      .for_each_parallel(
          threads,
          [](const LocalTransform& local, WorldTransform& world_transform) {
            world_transform.matrix = to_matrix(local);
          },
          motion_entities_per_task);

  Visited updated;
  std::vector<Entity> pending;
  // Shallowest first: by the time a dirty entity comes up, either an ancestor's subtree pass
  // already recomputed it, or none of its ancestors changed and its parent's matrix is current.
  for (const DirtyRoot& dirty : find_dirty(world, since)) {
    if (!updated.contains(dirty.entity)) update_subtree(world, dirty.entity, updated, pending);
  }
}

}  // namespace sg::ecs
