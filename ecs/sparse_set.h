// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ecs/entity.h"
#include "ecs/fwd.h"
#include "ecs/large_array.h"

namespace sg::ecs {

// A component type's removal history entry.
struct Removal {
  Entity entity;
  Tick tick;  // when the component was removed or its entity destroyed
};

// The type-independent half of a component pool: which entities have the component, at which
// dense slot, the history of changes and, where asked for, of removals.
//
// Membership is a classic sparse set: `sparse_[entity.index]` points into the dense arrays, and
// the dense entity array is checked on every lookup by handle, so stale handles never match
// (queries, whose entities are known to be alive, skip that check: see LiveLookup). Removal
// swaps the last element into the hole and clears the removed entity's sparse entry, which
// keeps the dense arrays contiguous and every operation O(1).
//
// Change history is a tick per slot, the tick of the component's newest write, plus two levels
// of summaries: the newest tick in each block of 16 slots and in each group of 256. Ticks only
// grow, so a write is three plain stores (no branch, no log, nothing to compact later, so no
// tick ever pays for older ones). Reading "changed since T" reads every group summary, the
// block summaries of groups written after T and the slot ticks of blocks written after T: for
// scattered changes about one cache line per change, plus summaries read sequentially (1/256 of
// the pool's size, up to 1/16 when changes touch every group). Summaries may be stale high
// after a removal moves a slot; readers check slots.
//
// A query that writes every component of the pool records that as one bulk mark instead of a
// store per component: every component present then changed at `bulk_tick_`, which counts as
// the tick of any slot whose own tick is older. This keeps a full per-frame update as cheap as
// a plain loop.
class SparseSet {
 public:
  static constexpr std::uint32_t npos = UINT32_MAX;
  // Change summaries cover this many slots each; 16 ticks fill one cache line.
  static constexpr std::uint32_t slots_per_block = 16;
  static constexpr std::uint32_t slots_per_group = 256;

  SparseSet() = default;
  SparseSet(const SparseSet&) = delete;
  SparseSet& operator=(const SparseSet&) = delete;
  virtual ~SparseSet() = default;

  std::size_t size() const { return dense_.size(); }
  std::span<const Entity> entities() const { return dense_; }

  bool contains(Entity entity) const { return slot_of(entity) != npos; }

  // Dense slot of `entity`, or npos.
  std::uint32_t slot_of(Entity entity) const {
    if (entity.index >= sparse_.size()) return npos;
    const std::uint32_t slot = sparse_[entity.index];
    return slot < dense_.size() && dense_[slot] == entity ? slot : npos;
  }

  // Looks up the dense slot, or npos, of an entity known to be alive (e.g. read from another
  // pool of the same world). One read of the sparse array: removal clears the entry and
  // destroying an entity removes it from every pool, so a live entity's index can only point at
  // its own slot, and the dense entity array (the generation check) stays untouched. Plain
  // pointers, so a loop can keep them in registers; valid until the next structural change.
  struct LiveLookup {
    const std::uint32_t* sparse;
    std::size_t size;
    std::uint32_t operator()(Entity entity) const {
      return entity.index < size ? sparse[entity.index] : npos;
    }
  };
  LiveLookup live_lookup() const { return {sparse_.data(), sparse_.size()}; }
  std::uint32_t slot_of_live(Entity entity) const { return live_lookup()(entity); }

  // True if `other` holds exactly the same entities in the same slots, so slot i of one pool
  // and slot i of the other belong to the same entity. The answer is cached until either pool
  // changes structurally, so asking every frame is O(1).
  bool has_same_layout(const SparseSet& other) const;
  // Names the entities and their slots as they are now: two stamps, from any pools of any
  // worlds, are equal only when they are this pool's with no insert, erase or reordering
  // between them. O(1); not to be called concurrently with itself.
  std::uint64_t layout_stamp() const;

  // Records a write at `now`, the world's current tick, to the component in a slot. Calls for
  // different slots may run concurrently (a parallel query): the slot tick is the caller's
  // alone, and neighbours share summaries, which are written atomically (all with the same
  // `now`, so any order is right). Plain pointers like LiveLookup, with the same validity.
  // Inlined by force: called out of line from a query's loop, the call stalled on the tick's
  // store while the loop's prefetches waited (a scattered write through lookups 14.0-14.6 ns an
  // entity against 12.6-12.8 inlined, 2-core EPYC VM, 2026-12-05).
  struct ChangeMarker {
    Tick* ticks;
    Tick* block_ticks;
    Tick* group_ticks;
    [[gnu::always_inline]] void operator()(std::uint32_t slot, Tick now) const {
      ticks[slot] = now;
      mark_summary(block_ticks[slot / slots_per_block], now);
      mark_summary(group_ticks[slot / slots_per_group], now);
    }
  };
  ChangeMarker change_marker() { return {ticks_.data(), block_ticks_.data(), group_ticks_.data()}; }
  void mark_changed(std::uint32_t slot, Tick now) { change_marker()(slot, now); }

  // Records a write at `now` to every component in the pool, in O(1).
  void mark_all_changed(Tick now) { bulk_tick_ = now; }
  // Records a write at `now` to the components in slots [begin, end): a fill, no per-slot
  // branch. Disjoint ranges may be marked concurrently, as ChangeMarker calls may.
  void mark_range_changed(std::uint32_t begin, std::uint32_t end, Tick now);

  // Tick of the newest write to the component of the entity in `slot`.
  Tick change_tick(std::uint32_t slot) const { return std::max(ticks_[slot], bulk_tick_); }

  // Appends to `out` the slot of every component written after `since`, each once, in slot
  // order.
  void collect_changed_since(Tick since, std::vector<std::uint32_t>& out) const;

  // From now on, removals are recorded (removed_since). Off by default: a record per removed
  // component is most of what destroying an entity costs, and most types' removals have no
  // reader.
  void keep_removals() { keeps_removals_ = true; }
  bool keeps_removals() const { return keeps_removals_; }
  // Removals after `since`, oldest first; throws std::logic_error unless keep_removals() was
  // called.
  std::span<const Removal> removed_since(Tick since) const;
  void forget_removals_before(Tick tick);

  // True while the entities sit in ascending index order, as creating them and adding their
  // components in one pass leaves them: pools in that order that hold the same entities share a
  // layout. Appending a higher index keeps it; swap-removing before the last slot breaks it.
  bool in_entity_order() const { return in_entity_order_; }
  // Reorders the pool into ascending entity index order, keeping each component's change tick;
  // O(size + highest index). A structural change: references and queries are invalidated.
  void sort_by_entity();

  // The owning group that keeps this pool's order (World::group), or null.
  OwningGroup* owner() const { return owner_; }
  void set_owner(OwningGroup* group) { owner_ = group; }
  // Exchanges two slots' entities, change ticks and components (an owning group's reordering).
  void swap_slots(std::uint32_t a, std::uint32_t b);

  // Removes the entity's component, recording the removal at `now`. Returns false if absent.
  virtual bool remove(Entity entity, Tick now) = 0;
  // Same as remove for each entity, without a virtual call per entity; handles that are stale,
  // repeated or without the component are skipped.
  virtual void remove_many(std::span<const Entity> entities, Tick now) = 0;

 protected:
  // Adds the entity to the set, marked as changed at `now`; returns its dense slot. The typed
  // pool appends the component itself.
  std::uint32_t insert(Entity entity, Tick now);
  // Adds entities that are not in the set yet, marked as changed at `now`, growing each array
  // once. The typed pool appends their components.
  void insert_many(std::span<const Entity> entities, Tick now);
  // Removes the entities' components by one sequential pass that keeps the others in order,
  // recording each removal at `now` (where removals are kept); cheaper than swap-removes once a
  // good share of the pool goes. Returns the mask of removed slots (by old slot); the typed pool
  // compacts its component array with it.
  std::vector<bool> erase_many(std::span<const Entity> entities, Tick now);
  // Swap-removes `slot` from the membership arrays, recording the removal at `now` (where
  // removals are kept). The typed
  // pool must do the same swap on its component array.
  void erase(std::uint32_t slot, Tick now);
  // The typed pool's half of swap_slots.
  virtual void swap_components(std::uint32_t a, std::uint32_t b) = 0;
  // The typed pool's half of sort_by_entity: new slot i takes the component of `old_slots[i]`.
  virtual void permute_components(std::span<const std::uint32_t> old_slots) = 0;

 private:
  // Sets a summary tick to `now`, storing only if it differs: after the first write of a tick,
  // threads that mark slots under the same summary only read it, so its cache line stays shared
  // among their cores instead of moving to each writer in turn.
  static void mark_summary(Tick& summary, Tick now) {
    std::atomic_ref<Tick> tick(summary);
    if (tick.load(std::memory_order_relaxed) != now) tick.store(now, std::memory_order_relaxed);
  }

  struct LayoutComparison {
    const SparseSet* other;
    std::uint64_t version;
    std::uint64_t other_version;
    bool same;
  };

  LargeArray<std::uint32_t> sparse_;  // entity index -> dense slot, npos when absent
  LargeArray<Entity> dense_;          // dense slot -> entity
  LargeArray<Tick> ticks_;            // dense slot -> tick of the newest write
  LargeArray<Tick> block_ticks_;      // newest tick among slots_per_block slots
  LargeArray<Tick> group_ticks_;      // newest tick among slots_per_group slots
  Tick bulk_tick_ = 0;                // last mark_all_changed; 0 if never
  bool keeps_removals_ = false;
  bool in_entity_order_ = true;
  OwningGroup* owner_ = nullptr;
  std::vector<Removal> removals_;     // ascending ticks; empty unless keeps_removals_
  std::uint64_t layout_version_ = 0;  // bumped by every insert and erase
  mutable std::vector<LayoutComparison> layout_comparisons_;
  mutable std::uint64_t stamp_ = 0;  // layout_stamp() of stamped_version_
  mutable std::uint64_t stamped_version_ = ~std::uint64_t{0};
};

}  // namespace sg::ecs
