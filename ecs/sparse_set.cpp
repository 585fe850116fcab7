// SPDX-License-Identifier: MIT
#include "ecs/sparse_set.h"

#include <algorithm>
#include <stdexcept>

namespace sg::ecs {

bool SparseSet::has_same_layout(const SparseSet& other) const {
  if (&other == this) return true;
  if (other.dense_.size() != dense_.size()) return false;
  auto known = std::find_if(layout_comparisons_.begin(), layout_comparisons_.end(),
                            [&](const LayoutComparison& comparison) { return comparison.other == &other; });
  if (known == layout_comparisons_.end()) {
    known = layout_comparisons_.insert(known, LayoutComparison{&other, 0, 0, false});
  } else if (known->version == layout_version_ && known->other_version == other.layout_version_) {
    return known->same;
  }
  *known = LayoutComparison{&other, layout_version_, other.layout_version_,
                            std::equal(dense_.begin(), dense_.end(), other.dense_.begin())};
  return known->same;
}

std::uint64_t SparseSet::layout_stamp() const {
  // Drawn from one counter for every pool, so that no two pools ever share a stamp.
  static std::atomic<std::uint64_t> next_stamp{1};
  if (stamped_version_ != layout_version_) {
    stamp_ = next_stamp.fetch_add(1, std::memory_order_relaxed);
    stamped_version_ = layout_version_;
  }
  return stamp_;
}

void SparseSet::mark_range_changed(std::uint32_t begin, std::uint32_t end, Tick now) {
  if (begin >= end) return;
  std::fill(ticks_.begin() + begin, ticks_.begin() + end, now);
  // Neighbouring ranges share the summaries at their ends: relaxed atomic stores of one tick.
  for (std::uint32_t block = begin / slots_per_block; block <= (end - 1) / slots_per_block; ++block) {
    mark_summary(block_ticks_[block], now);
  }
  for (std::uint32_t group = begin / slots_per_group; group <= (end - 1) / slots_per_group; ++group) {
    mark_summary(group_ticks_[group], now);
  }
}

void SparseSet::swap_slots(std::uint32_t a, std::uint32_t b) {
  if (a == b) return;
  swap_components(a, b);
  std::swap(dense_[a], dense_[b]);
  std::swap(ticks_[a], ticks_[b]);
  sparse_[dense_[a].index] = a;
  sparse_[dense_[b].index] = b;
  in_entity_order_ = false;
  // Each tick moved to a slot whose summaries must stay upper bounds.
  for (const std::uint32_t slot : {a, b}) {
    block_ticks_[slot / slots_per_block] = std::max(block_ticks_[slot / slots_per_block], ticks_[slot]);
    group_ticks_[slot / slots_per_group] = std::max(group_ticks_[slot / slots_per_group], ticks_[slot]);
  }
  ++layout_version_;
}

void SparseSet::sort_by_entity() {
  if (in_entity_order_) return;
  // The sparse array lists the members by index already: one pass over it is the sorted order.
  std::vector<std::uint32_t> old_slots;
  old_slots.reserve(dense_.size());
  for (const std::uint32_t slot : sparse_) {
    if (slot != npos) old_slots.push_back(slot);
  }
  permute_components(old_slots);
  LargeArray<Entity> dense(dense_.size());
  LargeArray<Tick> ticks(ticks_.size());
  for (std::uint32_t slot = 0; slot < old_slots.size(); ++slot) {
    dense[slot] = dense_[old_slots[slot]];
    ticks[slot] = ticks_[old_slots[slot]];
    sparse_[dense[slot].index] = slot;
  }
  dense_.swap(dense);
  ticks_.swap(ticks);
  // Every tick moved, so the summaries are rebuilt exactly rather than raised.
  std::fill(block_ticks_.begin(), block_ticks_.end(), Tick{0});
  std::fill(group_ticks_.begin(), group_ticks_.end(), Tick{0});
  for (std::uint32_t slot = 0; slot < ticks_.size(); ++slot) {
    block_ticks_[slot / slots_per_block] = std::max(block_ticks_[slot / slots_per_block], ticks_[slot]);
    group_ticks_[slot / slots_per_group] = std::max(group_ticks_[slot / slots_per_group], ticks_[slot]);
  }
  in_entity_order_ = true;
  ++layout_version_;
}

void SparseSet::collect_changed_since(Tick since, std::vector<std::uint32_t>& out) const {
  if (bulk_tick_ > since) {
    // Everything present at the bulk mark changed then, and everything added since is newer.
    for (std::uint32_t slot = 0; slot < dense_.size(); ++slot) out.push_back(slot);
    return;
  }
  // Scattered changes make the summary tests unpredictable, so both passes append
  // unconditionally and advance only on a match instead of branching.
  std::vector<std::uint32_t> blocks(block_ticks_.size());
  std::size_t block_count = 0;
  const std::size_t blocks_per_group = slots_per_group / slots_per_block;
  for (std::size_t group = 0; group * slots_per_group < dense_.size(); ++group) {
    if (group_ticks_[group] <= since) continue;
    const std::size_t end_block = std::min((group + 1) * blocks_per_group, block_ticks_.size());
    for (std::size_t block = group * blocks_per_group; block < end_block; ++block) {
      blocks[block_count] = static_cast<std::uint32_t>(block);
      block_count += block_ticks_[block] > since;
    }
  }
  std::size_t found = out.size();
  out.resize(found + block_count * slots_per_block);
  for (std::size_t i = 0; i < block_count; ++i) {
    const std::size_t first = std::size_t{blocks[i]} * slots_per_block;
    const std::size_t end = std::min(dense_.size(), first + slots_per_block);
    for (std::size_t slot = first; slot < end; ++slot) {
      out[found] = static_cast<std::uint32_t>(slot);
      found += ticks_[slot] > since;
    }
  }
  out.resize(found);
}

std::span<const Removal> SparseSet::removed_since(Tick since) const {
  if (!keeps_removals_) {
    throw std::logic_error(
        "sg::ecs: removals of this component type are not kept; call World::keep_removals<T>() "
        "before the removals you want to read");
  }
  const auto first =
      std::upper_bound(removals_.begin(), removals_.end(), since,
                       [](Tick value, const Removal& removal) { return value < removal.tick; });
  return {first, removals_.end()};
}

void SparseSet::forget_removals_before(Tick tick) {
  const auto first_kept =
      std::lower_bound(removals_.begin(), removals_.end(), tick,
                       [](const Removal& removal, Tick value) { return removal.tick < value; });
  removals_.erase(removals_.begin(), first_kept);
}

std::uint32_t SparseSet::insert(Entity entity, Tick now) {
  if (entity.index >= sparse_.size()) sparse_.resize(entity.index + std::size_t{1}, npos);
  const auto slot = static_cast<std::uint32_t>(dense_.size());
  sparse_[entity.index] = slot;
  in_entity_order_ = in_entity_order_ && (dense_.empty() || dense_.back().index < entity.index);
  dense_.push_back(entity);
  ticks_.push_back(now);
  if (slot % slots_per_block == 0 && slot / slots_per_block == block_ticks_.size()) block_ticks_.push_back(0);
  if (slot % slots_per_group == 0 && slot / slots_per_group == group_ticks_.size()) group_ticks_.push_back(0);
  mark_changed(slot, now);
  ++layout_version_;
  return slot;
}

void SparseSet::insert_many(std::span<const Entity> entities, Tick now) {
  std::uint32_t max_index = 0;
  for (const Entity entity : entities) max_index = std::max(max_index, entity.index);
  if (!entities.empty() && max_index >= sparse_.size()) sparse_.resize(max_index + std::size_t{1}, npos);
  const std::size_t first = dense_.size();
  const std::size_t size = first + entities.size();
  dense_.insert(dense_.end(), entities.begin(), entities.end());
  for (std::size_t slot = std::max<std::size_t>(first, 1); slot < size && in_entity_order_; ++slot) {
    in_entity_order_ = dense_[slot - 1].index < dense_[slot].index;
  }
  ticks_.resize(size, now);
  block_ticks_.resize(std::max(block_ticks_.size(), (size + slots_per_block - 1) / slots_per_block));
  group_ticks_.resize(std::max(group_ticks_.size(), (size + slots_per_group - 1) / slots_per_group));
  for (std::size_t slot = first; slot < size; ++slot) {
    sparse_[dense_[slot].index] = static_cast<std::uint32_t>(slot);
    block_ticks_[slot / slots_per_block] = now;
  }
  for (std::size_t group = first / slots_per_group;
       group < group_ticks_.size() && group * slots_per_group < size; ++group) {
    group_ticks_[group] = now;
  }
  ++layout_version_;
}

std::vector<bool> SparseSet::erase_many(std::span<const Entity> entities, Tick now) {
  std::vector<bool> doomed(dense_.size(), false);
  if (keeps_removals_) removals_.reserve(removals_.size() + entities.size());
  std::size_t doomed_count = 0;
  for (const Entity entity : entities) {
    const std::uint32_t slot = slot_of(entity);
    if (slot == npos || doomed[slot]) continue;
    doomed[slot] = true;
    sparse_[entity.index] = npos;
    if (keeps_removals_) removals_.push_back(Removal{entity, now});
    ++doomed_count;
  }
  if (doomed_count == dense_.size()) {  // all of them, as when a scene is unloaded: nothing to keep
    dense_.clear();
    ticks_.clear();
    in_entity_order_ = true;
    ++layout_version_;
    return doomed;
  }
  std::size_t kept = 0;
  for (std::size_t slot = 0; slot < dense_.size(); ++slot) {
    if (doomed[slot]) continue;
    dense_[kept] = dense_[slot];
    ticks_[kept] = ticks_[slot];
    sparse_[dense_[kept].index] = static_cast<std::uint32_t>(kept);
    // Ticks move to lower slots, whose summaries must stay upper bounds.
    block_ticks_[kept / slots_per_block] = std::max(block_ticks_[kept / slots_per_block], ticks_[kept]);
    group_ticks_[kept / slots_per_group] = std::max(group_ticks_[kept / slots_per_group], ticks_[kept]);
    ++kept;
  }
  dense_.resize(kept);
  ticks_.resize(kept);
  ++layout_version_;
  return doomed;
}

void SparseSet::erase(std::uint32_t slot, Tick now) {
  const Entity removed = dense_[slot];
  const Entity last = dense_.back();
  in_entity_order_ = in_entity_order_ && slot + std::size_t{1} == dense_.size();
  dense_[slot] = last;
  ticks_[slot] = ticks_.back();
  // The moved tick may be older than the hole's block: summaries only need to be upper bounds.
  block_ticks_[slot / slots_per_block] = std::max(block_ticks_[slot / slots_per_block], ticks_[slot]);
  group_ticks_[slot / slots_per_group] = std::max(group_ticks_[slot / slots_per_group], ticks_[slot]);
  sparse_[last.index] = slot;
  sparse_[removed.index] = npos;
  dense_.pop_back();
  ticks_.pop_back();
  if (keeps_removals_) removals_.push_back(Removal{removed, now});
  ++layout_version_;
}

}  // namespace sg::ecs
