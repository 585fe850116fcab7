// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "ecs/owning_group.h"
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
    components_.emplace_back(T{std::forward<Args>(args)...});
    if (owner() == nullptr) return components_.back();
    owner()->joined_pool(entity);
    return components_[slot_of_live(entity)];
  }

  bool remove(Entity entity, Tick now) override {
    if (owner() != nullptr) owner()->leaving_pool(*this, entity);
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
    if (owner() != nullptr) {
      for (const Entity entity : entities) owner()->joined_pool(entity);
    }
  }

  void remove_many(std::span<const Entity> entities, Tick now) override {
    if (size() == 0) return;
    // Below 1/16 of the pool, swap-removes touch less memory than a full pass.
    if (entities.size() * 16 < size()) {
      for (const Entity entity : entities) remove(entity, now);
      return;
    }
    // Members leave the group first, so the pass below only removes slots behind its prefix and,
    // keeping the others' order, leaves the prefix as it is.
    if (owner() != nullptr) {
      for (const Entity entity : entities) owner()->leaving_pool(*this, entity);
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
  void swap_components(std::uint32_t a, std::uint32_t b) override {
    std::swap(components_[a], components_[b]);
  }
  void permute_components(std::span<const std::uint32_t> old_slots) override {
    LargeArray<T> sorted;
    sorted.reserve(old_slots.size());
    for (const std::uint32_t slot : old_slots) sorted.push_back(std::move(components_[slot]));
    components_.swap(sorted);
  }

  LargeArray<T> components_;
};

}  // namespace sg::ecs
