#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ecs/entity.h"

namespace sg::ecs {

// Hands out entity handles and knows which ones are alive. Slots of destroyed entities are
// reused with a new generation; a slot whose generation would wrap around is retired for good,
// so a stale handle can never match a live entity.
class EntityRegistry {
 public:
  Entity create();
  // Appends `count` new handles to `out`, reusing free slots first; grows the slot array once.
  void create_many(std::size_t count, std::vector<Entity>& out);
  // Returns false (and does nothing) for a stale or null handle.
  bool destroy(Entity entity);
  // Same as destroy for each handle, growing the free list once; returns how many were alive.
  std::size_t destroy_many(std::span<const Entity> entities);
  bool alive(Entity entity) const;
  std::size_t alive_count() const { return alive_count_; }

 private:
  struct Slot {
    std::uint32_t generation = 0;  // of the live entity, or of the next one while free
    bool alive = false;
  };
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_slots_;
  std::size_t alive_count_ = 0;
};

}  // namespace sg::ecs
