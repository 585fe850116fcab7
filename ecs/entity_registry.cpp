// SPDX-License-Identifier: MIT
#include "ecs/entity_registry.h"

namespace sg::ecs {

namespace {
// The last generation is never handed out: null_entity uses it.
constexpr std::uint32_t retired_generation = UINT32_MAX;
}  // namespace

Entity EntityRegistry::create() {
  ++alive_count_;
  if (first_free_ != no_slot) {
    const std::uint32_t index = first_free_;
    Slot& slot = slots_[index];
    first_free_ = slot.next_free;
    slot.next_free = live;
    return Entity{index, slot.generation};
  }
  const auto index = static_cast<std::uint32_t>(slots_.size());
  slots_.push_back(Slot{0, live});
  return Entity{index, 0};
}

void EntityRegistry::create_many(std::size_t count, std::vector<Entity>& out) {
  out.reserve(out.size() + count);
  for (; count > 0 && first_free_ != no_slot; --count) out.push_back(create());
  const auto first = static_cast<std::uint32_t>(slots_.size());
  slots_.resize(slots_.size() + count, Slot{0, live});
  for (std::uint32_t index = first; index < slots_.size(); ++index) out.push_back(Entity{index, 0});
  alive_count_ += count;
}

bool EntityRegistry::destroy(Entity entity) {
  if (!alive(entity)) return false;
  --alive_count_;
  Slot& slot = slots_[entity.index];
  // Bumping now is what makes every old handle stale.
  if (++slot.generation != retired_generation) {
    slot.next_free = first_free_;
    first_free_ = entity.index;
  } else {
    slot.next_free = no_slot;  // retired: neither alive nor free
  }
  return true;
}

std::size_t EntityRegistry::destroy_many(std::span<const Entity> entities) {
  std::size_t destroyed = 0;
  for (const Entity entity : entities) destroyed += destroy(entity) ? 1 : 0;
  return destroyed;
}

}  // namespace sg::ecs
