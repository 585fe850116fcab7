#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "ecs/sparse_set.h"

namespace sg::ecs {

// Dense storage of one component type: `components_[slot]` belongs to `entities()[slot]`.
template <typename T>
class ComponentPool final : public SparseSet {
 public:
  // Adds the component, or replaces it if the entity already has one; marks it changed.
  template <typename... Args>
  T& emplace(Entity entity, Tick now, Args&&... args) {
    if (const std::uint32_t slot = slot_of(entity); slot != npos) {
      components_[slot] = T{std::forward<Args>(args)...};
      mark_changed(slot, now);
      return components_[slot];
    }
    insert(entity, now);
    return components_.emplace_back(T{std::forward<Args>(args)...});
  }

  bool remove(Entity entity, Tick now) override {
    const std::uint32_t slot = slot_of(entity);
    if (slot == npos) return false;
    if (slot + std::size_t{1} != components_.size()) components_[slot] = std::move(components_.back());
    components_.pop_back();
    erase(slot, now);
    return true;
  }

  // Adds a copy of `value` for each entity; none of them may have the component yet.
  void emplace_many(std::span<const Entity> entities, Tick now, const T& value) {
    insert_many(entities, now);
    components_.insert(components_.end(), entities.size(), value);
  }

  void remove_many(std::span<const Entity> entities, Tick now) override {
    if (size() == 0) return;
    // Below 1/16 of the pool, swap-removes touch less memory than a full pass.
    if (entities.size() * 16 < size()) {
      for (const Entity entity : entities) remove(entity, now);
      return;
    }
    const std::vector<bool> doomed = erase_many(entities, now);
    if (size() == 0) {
      components_.clear();
      return;
    }
    std::size_t kept = 0;
    for (std::size_t slot = 0; slot < components_.size(); ++slot) {
      if (!doomed[slot]) components_[kept++] = std::move(components_[slot]);
    }
    components_.erase(components_.begin() + static_cast<std::ptrdiff_t>(kept), components_.end());
  }

  T* data() { return components_.data(); }
  T& at(std::uint32_t slot) { return components_[slot]; }
  const T& at(std::uint32_t slot) const { return components_[slot]; }

 private:
  LargeArray<T> components_;
};

}  // namespace sg::ecs
