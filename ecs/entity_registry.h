// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ecs/entity.h"
#include "ecs/large_array.h"

namespace sg::ecs {

// Hands out entity handles and knows which ones are alive. Slots of destroyed entities are
// reused with a new generation, last freed first; a slot whose generation would wrap around is
// retired for good, so a stale handle can never match a live entity. The free slots form a list
// threaded through the slots themselves: destroying needs no memory of its own (a separate free
// list was a fresh page every 1,024 entities of a bulk destroy).
class EntityRegistry {
 public:
  Entity create();
  // Appends `count` new handles to `out`, reusing free slots first; grows the slot array once.
  void create_many(std::size_t count, std::vector<Entity>& out);
  // Returns false (and does nothing) for a stale or null handle.
  bool destroy(Entity entity);
  // Same as destroy for each handle; returns how many were alive.
  std::size_t destroy_many(std::span<const Entity> entities);
  // Inline: World::alive guards every add, and destroy asks once per handle.
  bool alive(Entity entity) const {
    return entity.index < slots_.size() && slots_[entity.index].next_free == live &&
           slots_[entity.index].generation == entity.generation;
  }
  std::size_t alive_count() const { return alive_count_; }

 private:
  static constexpr std::uint32_t live = UINT32_MAX;         // Slot::next_free of a live entity's slot
  static constexpr std::uint32_t no_slot = UINT32_MAX - 1;  // the free list's end; a retired slot's link
  struct Slot {
    std::uint32_t generation = 0;    // of the live entity, or of the next one while free
    std::uint32_t next_free = live;  // live, or the next free slot (no_slot: none)
  };
  LargeArray<Slot> slots_;
  std::uint32_t first_free_ = no_slot;
  std::size_t alive_count_ = 0;
};

}  // namespace sg::ecs
