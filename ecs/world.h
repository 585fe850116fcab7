// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/component_id.h"
#include "ecs/component_pool.h"
#include "ecs/entity.h"
#include "ecs/entity_registry.h"
#include "ecs/fwd.h"

namespace sg::ecs {

// Entities and their components. Any copyable or movable struct is a component; nothing needs
// registering.
//
// Contract:
// - Handles of destroyed entities are stale: `alive` and `has` return false for them, `destroy`
//   and `remove` do nothing and return false, `add`, `get` and `get_mut` throw.
// - Every write access (`add`, `get_mut`, a query's non-const component) stamps the component
//   with `tick()`. `advance_tick()` starts the next tick, typically once per frame.
// - Component references and queries stay valid until the next structural change (create,
//   destroy, add, remove). During iteration, make structural changes through a CommandBuffer.
class World {
 public:
  Entity create() { return entities_.create(); }
  // Creates `count` entities, each with a copy of every given component, and returns their
  // handles in creation order. Every array grows once, so this is about twice as fast per
  // entity as create and add in a loop. The components' pools keep the entities in the same
  // order, so later queries over exactly these components take the plain-loop path.
  template <typename... Components>
  std::vector<Entity> create_many(std::size_t count, const Components&... components) {
    static_assert(((count_of<Components, Components...> == 1) && ...),
                  "create_many takes each component type once");
    std::vector<Entity> created;
    entities_.create_many(count, created);
    (pool<Components>().emplace_many(created, tick_, components), ...);
    return created;
  }
  // Removes all of the entity's components (recording each removal where its type keeps them:
  // keep_removals) and makes its handle stale. Returns false for a stale handle.
  bool destroy(Entity entity);
  // Same as destroy for each entity (stale and repeated handles are skipped), one component
  // pool at a time. Returns how many were destroyed.
  std::size_t destroy_many(std::span<const Entity> entities);
  bool alive(Entity entity) const { return entities_.alive(entity); }
  std::size_t entity_count() const { return entities_.alive_count(); }

  Tick tick() const { return tick_; }
  // Starts the next tick, typically once per frame. Between frames it is also when the pools
  // that a query found holding the same entities as its other pools in another order are put
  // into entity order (a structural change: see Query), after which that query is a plain loop.
  Tick advance_tick();

  // Adds the component (or replaces the existing one) and marks it changed.
  template <typename T, typename... Args>
  T& add(Entity entity, Args&&... args) {
    if (!alive(entity)) throw std::invalid_argument("sg::ecs::World::add: stale entity handle");
    return pool<T>().emplace(entity, tick_, std::forward<Args>(args)...);
  }

  // Returns false if the entity has no such component (or the handle is stale).
  template <typename T>
  bool remove(Entity entity) {
    SparseSet* set = find_pool<T>();
    return set != nullptr && set->remove(entity, tick_);
  }

  template <typename T>
  bool has(Entity entity) const {
    const SparseSet* set = find_pool<T>();
    return set != nullptr && set->contains(entity);
  }

  // Read access; does not mark the component changed. Returns nullptr if absent.
  template <typename T>
  const T* try_get(Entity entity) const {
    const ComponentPool<T>* components = find_pool<T>();
    if (components == nullptr) return nullptr;
    const std::uint32_t slot = components->slot_of(entity);
    return slot == SparseSet::npos ? nullptr : &components->at(slot);
  }

  // Read access; throws std::out_of_range if absent.
  template <typename T>
  const T& get(Entity entity) const {
    const T* component = try_get<T>(entity);
    if (component == nullptr) throw std::out_of_range("sg::ecs::World::get: no such component");
    return *component;
  }

  // Write access; marks the component changed. Throws std::out_of_range if absent.
  template <typename T>
  T& get_mut(Entity entity) {
    ComponentPool<T>* components = find_pool<T>();
    const std::uint32_t slot = components == nullptr ? SparseSet::npos : components->slot_of(entity);
    if (slot == SparseSet::npos) {
      throw std::out_of_range("sg::ecs::World::get_mut: no such component");
    }
    components->mark_changed(slot, tick_);
    return components->at(slot);
  }

  // The layout stamp of T's pool (SparseSet::layout_stamp): equal stamps mean the same entities
  // in the same order. 0 while the world has no pool of T.
  template <typename T>
  std::uint64_t layout_stamp() const {
    const SparseSet* set = find_pool<T>();
    return set != nullptr ? set->layout_stamp() : 0;
  }

  // Tick of the newest write to the entity's component; throws std::out_of_range if absent.
  template <typename T>
  Tick change_tick(Entity entity) const {
    const SparseSet* set = find_pool<T>();
    const std::uint32_t slot = set == nullptr ? SparseSet::npos : set->slot_of(entity);
    if (slot == SparseSet::npos) {
      throw std::out_of_range("sg::ecs::World::change_tick: no such component");
    }
    return set->change_tick(slot);
  }

  // Records from now on which entities lose a T (removed, or destroyed), for removed_since.
  // Removal history is kept only for the types that ask: recording it is most of what
  // destroying an entity costs.
  template <typename... T>
  void keep_removals() {
    (pool<T>().keep_removals(), ...);
  }

  template <typename T>
  bool keeps_removals() const {
    const SparseSet* set = find_pool<T>();
    return set != nullptr && set->keeps_removals();
  }

  // Entities that lost the component after `since` (removed, or destroyed), oldest first. An
  // entity may appear more than once and may have the component again by now. Throws
  // std::logic_error unless keep_removals<T>() was called (before the removals to be read).
  template <typename T>
  std::span<const Removal> removed_since(Tick since) const {
    const SparseSet* set = find_pool<T>();
    if (set == nullptr) {
      throw std::logic_error("sg::ecs::World::removed_since: call keep_removals<T>() first");
    }
    return set->removed_since(since);
  }

  // Removal history is kept until dropped: call this with the oldest tick any reader will still
  // ask about.
  void forget_removals_before(Tick tick);

  // Declares an owning group (ecs/owning_group.h): from now on the entities that have every one
  // of `Owned` stay at the front of those pools, in one order, and queries over (at least) these
  // components walk them as parallel arrays instead of looking each one up. Costs a swap per
  // owned pool when an entity joins or leaves the group, and the owned pools no longer keep
  // create_many's order for queries over other component sets. Declaring the same set again
  // returns the existing group; throws std::logic_error if one of the pools is another group's.
  template <typename... Owned>
  const OwningGroup& group() {
    static_assert(sizeof...(Owned) >= 2, "a group owns at least two component types");
    static_assert(((count_of<Owned, Owned...> == 1) && ...), "group takes each component type once");
    std::vector<SparseSet*> owned{&pool<Owned>()...};
    const OwningGroup* existing = owned.front()->owner();
    if (existing != nullptr && existing->pools().size() == owned.size() &&
        std::all_of(owned.begin(), owned.end(),
                    [&](const SparseSet* set) { return set->owner() == existing; })) {
      return *existing;
    }
    groups_.push_back(std::make_unique<OwningGroup>(std::move(owned)));
    return *groups_.back();
  }

  // Iterates the entities that have every listed component; see ecs/query.h.
  template <typename... Components>
  Query<Components...> query() {
    return Query<Components...>(*this);
  }
  // Read-only: every listed component must be const, and nothing is marked changed.
  template <typename... Components>
  Query<Components...> query() const {
    static_assert((std::is_const_v<Components> && ...),
                  "a const World gives read-only queries: list the components as const");
    return Query<Components...>(*this);
  }

 private:
  template <typename... Components>
  friend class Query;

  template <typename T, typename... Types>
  static constexpr std::size_t count_of = (std::size_t{std::is_same_v<T, Types>} + ... + 0);

  template <typename T>
  ComponentPool<T>& pool() {
    static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "component types are plain types");
    const std::uint32_t id = component_id<T>();
    if (id >= pools_.size()) pools_.resize(id + std::size_t{1});
    if (pools_[id] == nullptr) pools_[id] = std::make_unique<ComponentPool<T>>();
    return static_cast<ComponentPool<T>&>(*pools_[id]);
  }

  template <typename T>
  ComponentPool<T>* find_pool() const {
    const std::uint32_t id = component_id<T>();
    return id < pools_.size() ? static_cast<ComponentPool<T>*>(pools_[id].get()) : nullptr;
  }

  // Asked by a query that had to look its entities up in pools of one size; sorted at the next
  // advance_tick, never during a query (a callback may run another query over the same pools).
  void sort_by_entity_later(SparseSet& pool) const;
  // A changed-since query's list of the slots it visits, lent (empty) for the query's length and
  // given back for the next: gathering lights runs five such queries a frame, 100,000 slots each
  // with every light moving, and a callback may run another query, so one list per query running.
  std::vector<std::uint32_t> lend_slot_list() const;
  void give_back_slot_list(std::vector<std::uint32_t> list) const;

  EntityRegistry entities_;
  std::vector<std::unique_ptr<SparseSet>> pools_;  // by component_id; null if never used
  mutable std::vector<SparseSet*> pools_to_sort_;
  mutable std::vector<std::vector<std::uint32_t>> slot_lists_;  // lent by lend_slot_list
  std::vector<std::unique_ptr<OwningGroup>> groups_;
  Tick tick_ = 1;  // 0 is "before anything happened", so changed_since(0) means "ever"
};

}  // namespace sg::ecs
