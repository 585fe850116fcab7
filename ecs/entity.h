// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <functional>

namespace sg::ecs {

// A world's logical clock. Every write is stamped with the tick current at the time, so
// "changed since T" means "stamped with a tick greater than T". 32 bits last for over two
// years at 60 ticks per second.
using Tick = std::uint32_t;

// A handle to an entity: a slot index plus the generation the slot had when the entity was
// created. Destroying an entity bumps its slot's generation, so every old handle to it stops
// matching and is detected as stale instead of aliasing whatever reuses the slot.
struct Entity {
  std::uint32_t index = UINT32_MAX;
  std::uint32_t generation = UINT32_MAX;

  friend bool operator==(const Entity&, const Entity&) = default;
};

// Refers to no entity; never returned by World::create.
inline constexpr Entity null_entity{};

// The handle as one integer, generation << 32 | index: a key that, like the handle, never
// matches an entity that reuses the slot (the low 32 bits still index per-slot storage).
constexpr std::uint64_t entity_key(Entity entity) {
  return std::uint64_t{entity.generation} << 32 | entity.index;
}

}  // namespace sg::ecs

template <>
struct std::hash<sg::ecs::Entity> {
  std::size_t operator()(const sg::ecs::Entity& entity) const noexcept {
    return std::hash<std::uint64_t>{}(sg::ecs::entity_key(entity));
  }
};
