// SPDX-License-Identifier: MIT
#include "ecs/world.h"

namespace sg::ecs {

bool World::destroy(Entity entity) {
  if (!alive(entity)) return false;
  for (const std::unique_ptr<SparseSet>& set : pools_) {
    if (set != nullptr) set->remove(entity, tick_);
  }
  return entities_.destroy(entity);
}

std::size_t World::destroy_many(std::span<const Entity> entities) {
  // Pools match handles by generation and drop each slot once, so stale and repeated handles
  // need no filtering before the registry, which then counts only the live ones.
  for (const std::unique_ptr<SparseSet>& set : pools_) {
    if (set != nullptr) set->remove_many(entities, tick_);
  }
  return entities_.destroy_many(entities);
}

void World::forget_removals_before(Tick tick) {
  for (const std::unique_ptr<SparseSet>& set : pools_) {
    if (set != nullptr) set->forget_removals_before(tick);
  }
}

}  // namespace sg::ecs
