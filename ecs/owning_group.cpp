// SPDX-License-Identifier: MIT
#include "ecs/owning_group.h"

#include <algorithm>
#include <stdexcept>

#include "ecs/sparse_set.h"

namespace sg::ecs {

OwningGroup::OwningGroup(std::vector<SparseSet*> pools) : pools_(std::move(pools)) {
  for (SparseSet* pool : pools_) {
    if (pool->owner() != nullptr) throw std::logic_error("sg::ecs: a pool belongs to one group at most");
    pool->set_owner(this);
  }
  // A partition of the smallest pool: joined_pool swaps each member found to slot size_, which
  // only ever moves an entity already looked at (a non-member) to the slot being looked at.
  const SparseSet* smallest =
      *std::min_element(pools_.begin(), pools_.end(),
                        [](const SparseSet* a, const SparseSet* b) { return a->size() < b->size(); });
  for (std::size_t slot = 0; slot < smallest->size(); ++slot) joined_pool(smallest->entities()[slot]);
}

void OwningGroup::joined_pool(Entity entity) {
  const bool member = std::all_of(pools_.begin(), pools_.end(),
                                  [&](const SparseSet* pool) { return pool->contains(entity); });
  if (!member) return;
  for (SparseSet* pool : pools_) pool->swap_slots(pool->slot_of_live(entity), size_);
  ++size_;
}

void OwningGroup::leaving_pool(const SparseSet& pool, Entity entity) {
  const std::uint32_t slot = pool.slot_of(entity);
  if (slot == SparseSet::npos || slot >= size_) return;
  --size_;
  for (SparseSet* owned : pools_) owned->swap_slots(owned->slot_of_live(entity), size_);
}

}  // namespace sg::ecs
