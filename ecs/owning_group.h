// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ecs/entity.h"
#include "ecs/fwd.h"

namespace sg::ecs {

// Keeps the entities that have every one of its pools' components in the first size() slots of
// each of those pools, in the same order, so that a query over them walks parallel arrays with no
// lookup at all (EnTT's "owning group"). Sparse iteration through lookups reads one scattered
// sparse entry, component and change tick per visit, about twice the memory traffic of a
// hand-written index list; a group's members are as dense as the components of one pool.
//
// Declared through World::group; each pool belongs to at most one group. Kept up to date by the
// pools themselves: an entity that gains the last owned component it lacked is swapped into slot
// size() of every owned pool, one that loses one is swapped out of the prefix first. Those swaps
// reorder the pools, so component references are invalidated by structural changes as always.
class OwningGroup {
 public:
  // Takes ownership of the pools (none may have an owner yet) and gathers the current members.
  explicit OwningGroup(std::vector<SparseSet*> pools);
  OwningGroup(const OwningGroup&) = delete;
  OwningGroup& operator=(const OwningGroup&) = delete;

  std::span<SparseSet* const> pools() const { return pools_; }
  // Members: the entities in slots [0, size()) of every owned pool.
  std::uint32_t size() const { return size_; }

  // Called by an owned pool once `entity` has its component there (appended at the end).
  void joined_pool(Entity entity);
  // Called by an owned pool before it removes the component of `entity` (which may be stale or
  // absent there: then nothing happens).
  void leaving_pool(const SparseSet& pool, Entity entity);

 private:
  std::vector<SparseSet*> pools_;
  std::uint32_t size_ = 0;
};

}  // namespace sg::ecs
