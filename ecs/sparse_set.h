#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ecs/entity.h"

namespace sg::ecs {

// A component type's removal history entry.
struct Removal {
  Entity entity;
  Tick tick;  // when the component was removed or its entity destroyed
};

// The type-independent half of a component pool: which entities have the component, at which
// dense slot, and the history of changes and removals.
//
// Membership is a classic sparse set: `sparse_[entity.index]` points into the dense arrays, and
// the dense entity array is checked on every lookup, so stale handles never match. Removal swaps
// the last element into the hole, which keeps the dense arrays contiguous and every operation
// O(1).
//
// Change history is a log of entities in tick order, split into one segment per tick that saw a
// write. Each component remembers where its newest log entry is (`log_position_`); older entries
// for the same component are simply ignored, so a write costs one compare and, for the first
// write in a tick, one append. Reading "changed since T" visits only the segments after T, i.e.
// it costs the number of changes, not the number of components. The log is compacted (stale
// entries dropped) whenever it grows past twice the pool size, which keeps memory bounded with
// amortised O(1) cost per write.
//
// A query that writes every component of the pool records that as one bulk mark instead of a
// log entry per component: every component present then changed at `bulk_tick_`, so the whole
// log before it is dropped (log positions are global counters; those before `log_base_` mean
// "changed at bulk_tick_"). This keeps a full per-frame update as cheap as a plain loop.
class SparseSet {
 public:
  static constexpr std::uint32_t npos = UINT32_MAX;

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

  // Same as slot_of, but first tries `hint`: when pools hold the same entities in the same order
  // (the common case for components added together) this is a sequential read instead of a
  // random one.
  std::uint32_t slot_of(Entity entity, std::uint32_t hint) const {
    if (hint < dense_.size() && dense_[hint] == entity) return hint;
    return slot_of(entity);
  }

  // True if `other` holds exactly the same entities in the same slots, so slot i of one pool
  // and slot i of the other belong to the same entity. The answer is cached until either pool
  // changes structurally, so asking every frame is O(1).
  bool has_same_layout(const SparseSet& other) const;

  // Opens the change segment of tick `now` if needed and returns the log position where it
  // starts. A component whose newest entry is before that position has not been written yet in
  // this tick. Call once before a batch of mark_changed calls with the same `now`.
  std::uint64_t begin_changes(Tick now);

  // Records a write at the tick `segment_begin` was opened for.
  void mark_changed(std::uint32_t slot, std::uint64_t segment_begin) {
    if (log_position_[slot] >= segment_begin) return;
    log_position_[slot] = log_base_ + change_log_.size();
    change_log_.push_back(dense_[slot]);
  }

  // Records a write at `now` to every component in the pool, in O(1).
  void mark_all_changed(Tick now);

  // Tick of the newest write to the component of the entity in `slot`.
  Tick change_tick(std::uint32_t slot) const;

  // Appends to `out` every entity whose component was written after `since`, each once, in the
  // order of their newest write.
  void collect_changed_since(Tick since, std::vector<Entity>& out) const;

  // Removals after `since`, oldest first.
  std::span<const Removal> removed_since(Tick since) const;
  void forget_removals_before(Tick tick);

  // Removes the entity's component, recording the removal at `now`. Returns false if absent.
  virtual bool remove(Entity entity, Tick now) = 0;

 protected:
  // Adds the entity to the set, marked as changed at `now`; returns its dense slot. The typed
  // pool appends the component itself.
  std::uint32_t insert(Entity entity, Tick now);
  // Swap-removes `slot` from the membership arrays, recording the removal at `now`. The typed
  // pool must do the same swap on its component array.
  void erase(std::uint32_t slot, Tick now);

 private:
  struct Segment {
    Tick tick;
    std::uint64_t begin;  // global log position of this tick's first write
  };
  struct LayoutComparison {
    const SparseSet* other;
    std::uint64_t version;
    std::uint64_t other_version;
    bool same;
  };

  std::uint64_t end_of_log() const { return log_base_ + change_log_.size(); }
  bool is_newest_entry(std::uint64_t position) const;
  void compact_change_log();

  std::vector<std::uint32_t> sparse_;        // entity index -> dense slot (may be stale)
  std::vector<Entity> dense_;                // dense slot -> entity
  std::vector<std::uint64_t> log_position_;  // dense slot -> global position of newest entry
  std::vector<Entity> change_log_;           // change_log_[0] is at global position log_base_
  std::uint64_t log_base_ = 0;
  Tick bulk_tick_ = 0;                // last mark_all_changed; 0 if never
  std::vector<Segment> segments_;     // ascending ticks, all after bulk_tick_
  std::vector<Removal> removals_;     // ascending ticks
  std::uint64_t layout_version_ = 0;  // bumped by every insert and erase
  mutable std::vector<LayoutComparison> layout_comparisons_;
};

}  // namespace sg::ecs
