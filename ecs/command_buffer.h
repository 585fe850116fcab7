// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/world.h"

namespace sg::ecs {

// Records structural changes while a query is iterating and applies them afterwards, in the
// order they were recorded.
//
// `create` hands out the new entity's handle right away (only the entity registry is touched,
// which no query iterates), so later commands in the same buffer can refer to it; the entity
// has no components until `apply`. Commands aimed at an entity that is no longer alive when
// they are applied are skipped, so two systems may both queue the destruction of one entity.
class CommandBuffer {
 public:
  explicit CommandBuffer(World& world) : world_(&world) {}

  Entity create() { return world_->create(); }

  void destroy(Entity entity) {
    commands_.emplace_back([entity](World& world) { world.destroy(entity); });
  }

  // The component is copied into the buffer, hence the copyable requirement.
  template <typename T>
  void add(Entity entity, T component) {
    static_assert(std::is_copy_constructible_v<T>, "deferred components must be copyable");
    commands_.emplace_back([entity, component = std::move(component)](World& world) {
      if (world.alive(entity)) world.add<T>(entity, component);
    });
  }

  template <typename T>
  void remove(Entity entity) {
    commands_.emplace_back([entity](World& world) { world.remove<T>(entity); });
  }

  bool empty() const { return commands_.empty(); }

  // Runs and clears the recorded commands. Must not be called while a query iterates.
  void apply();

 private:
  World* world_;
  std::vector<std::function<void(World&)>> commands_;
};

}  // namespace sg::ecs
