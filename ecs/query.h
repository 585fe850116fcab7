// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/jobs/thread_pool.h"
#include "ecs/query.h"
#include "ecs/world.h"

namespace sg::ecs {

// Iterates the entities that have all of `Components`, e.g.
//
//   world.query<Position, const Velocity>().for_each([](Position& p, const Velocity& v) {...});
//
// A `const` component is read-only; every other listed component is marked changed for each
// entity visited. The callback takes the components in the listed order, optionally preceded
// by the Entity. Iteration walks the dense array of the smallest pool and pays one read of each
// other pool's sparse array per entity (no generation check: the entities come from a pool, so
// they are alive); the loop is fully inlined, no virtual call per entity. Change bookkeeping is
// touched only for the non-const components: three stores per entity, with no log to compact
// later (see SparseSet). When the query reads every pool of an owning group (World::group), it
// walks the group's members instead, which share a slot in those pools: no lookup there, and
// over exactly the group's components a plain loop like the one over aligned pools.
//
// Do not add or remove components or entities inside the callback (use a CommandBuffer);
// get_mut on any entity is fine. Queries cache which pools share a layout, so even a const World
// must not be queried from two threads at once: split one query with for_each_parallel instead.
template <typename... Components>
class Query {
  static_assert(sizeof...(Components) > 0, "a query needs at least one component");

 public:
  explicit Query(World& world) : world_(&world), pools_{&world.pool<std::remove_const_t<Components>>()...} {}
  // Read-only (World::query() const checks that every component is const). A component type the
  // world has never seen gets an empty pool, so the query visits nothing.
  explicit Query(const World& world)
      : world_(&world), pools_{existing_or_empty<std::remove_const_t<Components>>(world)...} {}

  // Skips entities that have any of `Excluded`.
  template <typename... Excluded>
  Query& without() {
    const auto exclude = [this](const SparseSet* pool) {
      if (pool != nullptr) excluded_.push_back(pool);
    };
    (exclude(world_->find_pool<Excluded>()), ...);
    return *this;
  }

  // Visits only entities whose `Watched` component (one of `Components`) was written after
  // `since`. Costs the number of such writes, not the number of entities.
  template <typename Watched>
  Query& changed_since(Tick since) {
    constexpr std::size_t position = index_of<std::remove_const_t<Watched>>();
    static_assert(position < sizeof...(Components), "the watched component must be queried");
    watched_ = std::get<position>(pools_);
    since_ = since;
    return *this;
  }

  template <typename Fn>
  void for_each(Fn&& fn) {
    run(fn, nullptr, default_entities_per_task);
  }

  // Same visits and change marks as for_each, split into chunks of consecutive entities that
  // `threads` runs concurrently. The callback is called from several threads at once, each call
  // for a different entity, so it may write the components it is passed and read anything no
  // call writes; it must not call the world's writing functions (add, remove, get_mut, create,
  // destroy) nor record into a CommandBuffer, which are not thread-safe. Visit order within a
  // chunk is for_each's; across chunks it is unspecified.
  //
  // `entities_per_task`: the default suits cheap callbacks over many entities; a callback that
  // costs tens of nanoseconds (a matrix, a sine) pays for its tasks' bookkeeping with fewer
  // entities, and thousands of them already share well in tasks of about a thousand.
  template <typename Fn>
  void for_each_parallel(jobs::ThreadPool& threads, Fn&& fn,
                         std::size_t entities_per_task = default_entities_per_task) {
    run(fn, &threads, entities_per_task);
  }
  // The same on `threads`, or for_each when it is null (systems that take an optional pool).
  template <typename Fn>
  void for_each_parallel(jobs::ThreadPool* threads, Fn&& fn,
                         std::size_t entities_per_task = default_entities_per_task) {
    run(fn, threads, entities_per_task);
  }

  // Number of entities for_each would visit (does not mark anything changed).
  std::size_t count() {
    std::size_t visited = 0;
    Query<const Components...> reader(*world_);
    reader.excluded_ = excluded_;
    reader.watched_ = watched_;
    reader.since_ = since_;
    reader.for_each([&](const auto&...) { ++visited; });
    return visited;
  }

 private:
  template <typename... Others>
  friend class Query;

  using Pools = std::tuple<ComponentPool<std::remove_const_t<Components>>*...>;

  template <typename T>
  static constexpr std::size_t index_of() {
    constexpr std::array matches{std::is_same_v<T, std::remove_const_t<Components>>...};
    return static_cast<std::size_t>(std::find(matches.begin(), matches.end(), true) - matches.begin());
  }

  template <typename T>
  static constexpr bool is_mutable = !std::is_const_v<T>;

  template <typename T>
  static ComponentPool<T>* existing_or_empty(const World& world) {
    static ComponentPool<T> empty;  // never written: only read-only queries use it
    ComponentPool<T>* pool = world.find_pool<T>();
    return pool != nullptr ? pool : &empty;
  }

  // Entities per parallel task by default: large enough that a task's bookkeeping is noise,
  // small enough that two to a few dozen threads share a million entities evenly.
  static constexpr std::size_t default_entities_per_task = 16384;

  template <typename Fn>
  void run(Fn& fn, jobs::ThreadPool* threads, std::size_t entities_per_task) {
    // An entity must have every component: one empty pool leaves nothing to visit (and no
    // change history to collect).
    if (std::apply([](const auto*... pools) { return ((pools->size() == 0) || ...); }, pools_)) return;
    const Tick now = world_->tick();
    if (watched_ == nullptr && visits_every_slot()) {
      // Every component is visited, so mutable pools take one bulk mark instead of one per slot.
      [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((is_mutable<Components> ? std::get<I>(pools_)->mark_all_changed(now) : void()), ...);
      }
      (std::index_sequence_for<Components...>{});
      jobs::run_in_pieces(threads, std::get<0>(pools_)->size(), entities_per_task,
                          [&](std::size_t begin, std::size_t end) { for_each_slot(fn, begin, end); });
      return;
    }
    if (watched_ != nullptr) {
      // Collected first, so writes made by the callback cannot change what this pass visits.
      std::vector<std::uint32_t> changed = world_->lend_slot_list();
      watched_->collect_changed_since(since_, changed);
      jobs::run_in_pieces(threads, changed.size(), entities_per_task,
                          [&](std::size_t begin, std::size_t end) {
                            visit_range(
                                watched_, [&](std::size_t i) { return changed[i]; }, begin, end, now, fn,
                                std::index_sequence_for<Components...>{}, nullptr);
                          });
      world_->give_back_slot_list(std::move(changed));
      return;
    }
    const auto identity = [](std::size_t i) { return static_cast<std::uint32_t>(i); };
    const SparseSet* driver = smallest_pool();
    if (const OwningGroup* group = covering_group(); group != nullptr && group->size() <= driver->size()) {
      // The group's members are the first slots of its pools, the same entity in each.
      const bool plain =
          excluded_.empty() &&
          std::apply([&](const auto*... pools) { return ((pools->owner() == group) && ...); }, pools_);
      jobs::run_in_pieces(threads, group->size(), entities_per_task, [&](std::size_t begin, std::size_t end) {
        if (plain) {
          mark_range_changed(begin, end, now);
          for_each_slot(fn, begin, end);
        } else {
          visit_range(group->pools().front(), identity, begin, end, now, fn,
                      std::index_sequence_for<Components...>{}, group);
        }
      });
      return;
    }
    sort_dense_pools_later();
    jobs::run_in_pieces(threads, driver->size(), entities_per_task, [&](std::size_t begin, std::size_t end) {
      visit_range(driver, identity, begin, end, now, fn, std::index_sequence_for<Components...>{}, nullptr);
    });
  }

  // Pools of one size that need lookups most likely hold the same entities in other orders (the
  // components were added in separate passes). Lookups into them are scattered, 20x a plain loop
  // over a million entities (ecs/README.md); in entity order they share slots, so from the next
  // tick on this query is that loop. Pools already in that order hold different entities and are
  // left as they are, so no pool is sorted twice for one query.
  void sort_dense_pools_later() const {
    std::apply(
        [&](auto*... pools) {
          const std::size_t size = std::get<0>(pools_)->size();
          if (((pools->size() != size || pools->owner() != nullptr) || ...)) return;
          ((pools->in_entity_order() ? void() : world_->sort_by_entity_later(*pools)), ...);
        },
        pools_);
  }

  // An owning group all of whose pools the query reads, or null: its members are the entities
  // with at least those components, without a lookup.
  const OwningGroup* covering_group() const {
    const OwningGroup* found = nullptr;
    const auto consider = [&](const SparseSet* pool) {
      const OwningGroup* group = pool->owner();
      if (found != nullptr || group == nullptr) return;
      const bool covered =
          std::all_of(group->pools().begin(), group->pools().end(), [&](const SparseSet* owned) {
            return std::apply([&](const auto*... pools) { return ((pools == owned) || ...); }, pools_);
          });
      if (covered) found = group;
    };
    std::apply([&](const auto*... pools) { (consider(pools), ...); }, pools_);
    return found;
  }

  void mark_range_changed(std::size_t begin, std::size_t end, Tick now) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((is_mutable<Components> ? std::get<I>(pools_)->mark_range_changed(static_cast<std::uint32_t>(begin),
                                                                         static_cast<std::uint32_t>(end), now)
                               : void()),
       ...);
    }
    (std::index_sequence_for<Components...>{});
  }

  // True when slot i of every pool is the same entity and nothing is excluded, so the query is
  // a plain loop over parallel arrays.
  bool visits_every_slot() const {
    const SparseSet& first = *std::get<0>(pools_);
    const bool aligned =
        std::apply([&](const auto*... pools) { return (first.has_same_layout(*pools) && ...); }, pools_);
    return aligned && std::all_of(excluded_.begin(), excluded_.end(),
                                  [](const SparseSet* excluded) { return excluded->size() == 0; });
  }

  // With no lookups left, the compiler can vectorise the loop like a hand-written one.
  template <typename Fn>
  void for_each_slot(Fn& fn, std::size_t begin, std::size_t end) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      const std::tuple data{std::get<I>(pools_)->data()...};
      const std::span<const Entity> entities = std::get<0>(pools_)->entities();
      for (std::size_t slot = begin; slot < end; ++slot) {
        if constexpr (std::is_invocable_v<Fn&, Entity, Components&...>) {
          fn(entities[slot], std::get<I>(data)[slot]...);
        } else {
          fn(std::get<I>(data)[slot]...);
        }
      }
    }
    (std::index_sequence_for<Components...>{});
  }

  const SparseSet* smallest_pool() const {
    const SparseSet* smallest = std::get<0>(pools_);
    std::apply(
        [&](const auto*... pools) {
          ((smallest = pools->size() < smallest->size() ? pools : smallest), ...);
        },
        pools_);
    return smallest;
  }

  // A lookup is two dependent loads, the sparse entry and then the component, which the
  // hardware prefetcher cannot follow; so the loop requests the sparse entries of the entity
  // 2 * prefetch_distance ahead and the components (and change ticks) of the one
  // prefetch_distance ahead.
  static constexpr std::size_t prefetch_distance = 32;

  static void prefetch(const void* address) { __builtin_prefetch(address); }
  static void prefetch_for_write(const void* address) { __builtin_prefetch(address, 1); }

  // Visits, for each i in [begin, end), the entity in slot slot_at(i) of `driver` if it has
  // every component and none of the excluded ones. The pools of `aligned_group` (null, or the
  // driver's group, visited within its members) share the driver's slot and need no lookup.
  // Every array is reached through a pointer held in a local, so the loop body is loads and
  // stores only.
  template <typename Fn, typename SlotAt, std::size_t... I>
  void visit_range(const SparseSet* driver, const SlotAt& slot_at, std::size_t begin, std::size_t end,
                   Tick now, Fn& fn, std::index_sequence<I...>, const OwningGroup* aligned_group) {
    const std::span<const Entity> entities = driver->entities();
    const std::array lookups{std::get<I>(pools_)->live_lookup()...};
    const std::array shares_slot{
        (std::get<I>(pools_) == driver ||
         (aligned_group != nullptr && std::get<I>(pools_)->owner() == aligned_group))...};
    const std::tuple data{std::get<I>(pools_)->data()...};
    const std::array markers{std::get<I>(pools_)->change_marker()...};
    std::vector<SparseSet::LiveLookup> excluded;
    for (const SparseSet* pool : excluded_) excluded.push_back(pool->live_lookup());
    const auto prefetch_sparse = [&](std::size_t pool, Entity entity) {
      if (!shares_slot[pool] && entity.index < lookups[pool].size)
        prefetch(&lookups[pool].sparse[entity.index]);
    };
    const auto prefetch_component = [&]<std::size_t J>(std::integral_constant<std::size_t, J>,
                                                       std::uint32_t slot) {
      if (slot == SparseSet::npos) return;
      if constexpr (is_mutable<std::tuple_element_t<J, std::tuple<Components...>>>) {
        prefetch_for_write(&std::get<J>(data)[slot]);
        prefetch_for_write(&markers[J].ticks[slot]);
      } else {
        prefetch(&std::get<J>(data)[slot]);
      }
    };
    for (std::size_t i = begin; i < end; ++i) {
      if (i + 2 * prefetch_distance < end) {
        const Entity ahead = entities[slot_at(i + 2 * prefetch_distance)];
        (prefetch_sparse(I, ahead), ...);
      }
      if (i + prefetch_distance < end) {
        const std::uint32_t ahead_slot = slot_at(i + prefetch_distance);
        const Entity ahead = entities[ahead_slot];
        (prefetch_component(std::integral_constant<std::size_t, I>{},
                            shares_slot[I] ? ahead_slot : lookups[I](ahead)),
         ...);
      }
      const std::uint32_t driver_slot = slot_at(i);
      const Entity entity = entities[driver_slot];
      std::array<std::uint32_t, sizeof...(Components)> slots{};
      const bool has_all =
          (((slots[I] = shares_slot[I] ? driver_slot : lookups[I](entity)) != SparseSet::npos) && ...);
      if (!has_all) continue;
      if (std::any_of(excluded.begin(), excluded.end(), [&](const SparseSet::LiveLookup& lookup) {
            return lookup(entity) != SparseSet::npos;
          })) {
        continue;
      }
      ((is_mutable<Components> ? markers[I](slots[I], now) : void()), ...);
      if constexpr (std::is_invocable_v<Fn&, Entity, Components&...>) {
        fn(entity, std::get<I>(data)[slots[I]]...);
      } else {
        fn(std::get<I>(data)[slots[I]]...);
      }
    }
  }

  const World* world_;
  Pools pools_;
  std::vector<const SparseSet*> excluded_;
  const SparseSet* watched_ = nullptr;
  Tick since_ = 0;
};

}  // namespace sg::ecs
