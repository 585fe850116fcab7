#include "ecs/world.h"

namespace sg::ecs {

bool World::destroy(Entity entity) {
  if (!alive(entity)) return false;
  for (const std::unique_ptr<SparseSet>& set : pools_) {
    if (set != nullptr) set->remove(entity, tick_);
  }
  return entities_.destroy(entity);
}

void World::forget_removals_before(Tick tick) {
  for (const std::unique_ptr<SparseSet>& set : pools_) {
    if (set != nullptr) set->forget_removals_before(tick);
  }
}

}  // namespace sg::ecs
