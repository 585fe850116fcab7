#include "ecs/entity_registry.h"

namespace sg::ecs {

namespace {
// The last generation is never handed out: null_entity uses it.
constexpr std::uint32_t retired_generation = UINT32_MAX;
}  // namespace

Entity EntityRegistry::create() {
  ++alive_count_;
  if (!free_slots_.empty()) {
    const std::uint32_t index = free_slots_.back();
    free_slots_.pop_back();
    slots_[index].alive = true;
    return Entity{index, slots_[index].generation};
  }
  const auto index = static_cast<std::uint32_t>(slots_.size());
  slots_.push_back(Slot{0, true});
  return Entity{index, 0};
}

void EntityRegistry::create_many(std::size_t count, std::vector<Entity>& out) {
  out.reserve(out.size() + count);
  for (; count > 0 && !free_slots_.empty(); --count) out.push_back(create());
  const auto first = static_cast<std::uint32_t>(slots_.size());
  slots_.resize(slots_.size() + count, Slot{0, true});
  for (std::uint32_t index = first; index < slots_.size(); ++index) out.push_back(Entity{index, 0});
  alive_count_ += count;
}

bool EntityRegistry::destroy(Entity entity) {
  if (!alive(entity)) return false;
  --alive_count_;
  Slot& slot = slots_[entity.index];
  slot.alive = false;
  // Bumping now is what makes every old handle stale.
  if (++slot.generation != retired_generation) free_slots_.push_back(entity.index);
  return true;
}

std::size_t EntityRegistry::destroy_many(std::span<const Entity> entities) {
  free_slots_.reserve(free_slots_.size() + entities.size());
  std::size_t destroyed = 0;
  for (const Entity entity : entities) destroyed += destroy(entity) ? 1 : 0;
  return destroyed;
}

bool EntityRegistry::alive(Entity entity) const {
  return entity.index < slots_.size() && slots_[entity.index].alive &&
         slots_[entity.index].generation == entity.generation;
}

}  // namespace sg::ecs
