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

  // Opens the change segment of tick `now` if needed and returns the log position where it
  // starts. A component whose newest entry is before that position has not been written yet in
  // this tick. Call once before a batch of mark_changed calls with the same `now`.
  std::uint32_t begin_changes(Tick now);

  // Records a write at the tick `segment_begin` was opened for.
  void mark_changed(std::uint32_t slot, std::uint32_t segment_begin) {
    if (log_position_[slot] >= segment_begin) return;
    log_position_[slot] = static_cast<std::uint32_t>(change_log_.size());
    change_log_.push_back(dense_[slot]);
  }

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
    std::uint32_t begin;  // first log position of this tick's writes
  };

  bool is_newest_entry(std::uint32_t position) const;
  void compact_change_log();

  std::vector<std::uint32_t> sparse_;        // entity index -> dense slot (may be stale)
  std::vector<Entity> dense_;                // dense slot -> entity
  std::vector<std::uint32_t> log_position_;  // dense slot -> its newest change_log_ entry
  std::vector<Entity> change_log_;
  std::vector<Segment> segments_;            // ascending ticks
  std::vector<Removal> removals_;            // ascending ticks
};

}  // namespace sg::ecs
