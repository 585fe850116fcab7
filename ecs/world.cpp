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
  std::vector<Entity> alive_ones;
  alive_ones.reserve(entities.size());
  for (const Entity entity : entities) {
    // Destroying in the registry first also drops repeats: a second copy is stale by then.
    if (entities_.destroy(entity)) alive_ones.push_back(entity);
  }
  for (const std::unique_ptr<SparseSet>& set : pools_) {
    if (set != nullptr) set->remove_many(alive_ones, tick_);
  }
  return alive_ones.size();
}

void World::forget_removals_before(Tick tick) {
  for (const std::unique_ptr<SparseSet>& set : pools_) {
    if (set != nullptr) set->forget_removals_before(tick);
  }
}

}  // namespace sg::ecs
