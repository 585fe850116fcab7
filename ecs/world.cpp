// SPDX-License-Identifier: MIT
#include "ecs/world.h"

#include <algorithm>

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

Tick World::advance_tick() {
  for (SparseSet* pool : pools_to_sort_) {
    if (pool->owner() == nullptr) pool->sort_by_entity();
  }
  pools_to_sort_.clear();
  return ++tick_;
}

void World::sort_by_entity_later(SparseSet& pool) const {
  if (std::find(pools_to_sort_.begin(), pools_to_sort_.end(), &pool) == pools_to_sort_.end()) {
    pools_to_sort_.push_back(&pool);
  }
}

std::vector<std::uint32_t> World::lend_slot_list() const {
  if (slot_lists_.empty()) return {};
  std::vector<std::uint32_t> list = std::move(slot_lists_.back());
  slot_lists_.pop_back();
  list.clear();
  return list;
}

void World::give_back_slot_list(std::vector<std::uint32_t> list) const {
  slot_lists_.push_back(std::move(list));
}

void World::forget_removals_before(Tick tick) {
  for (const std::unique_ptr<SparseSet>& set : pools_) {
    if (set != nullptr) set->forget_removals_before(tick);
  }
}

}  // namespace sg::ecs
