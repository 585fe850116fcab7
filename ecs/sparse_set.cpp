#include "ecs/sparse_set.h"

#include <algorithm>

namespace sg::ecs {

namespace {
// Small pools are not worth compacting often; this also keeps tiny pools from compacting on
// every tick.
constexpr std::size_t min_log_size_before_compaction = 1024;
}  // namespace

std::uint32_t SparseSet::begin_changes(Tick now) {
  if (!segments_.empty() && segments_.back().tick == now) return segments_.back().begin;
  if (change_log_.size() > 2 * dense_.size() + min_log_size_before_compaction) {
    compact_change_log();
  }
  const auto begin = static_cast<std::uint32_t>(change_log_.size());
  segments_.push_back(Segment{now, begin});
  return begin;
}

Tick SparseSet::change_tick(std::uint32_t slot) const {
  const std::uint32_t position = log_position_[slot];
  const auto after = std::upper_bound(
      segments_.begin(), segments_.end(), position,
      [](std::uint32_t value, const Segment& segment) { return value < segment.begin; });
  return std::prev(after)->tick;
}

bool SparseSet::is_newest_entry(std::uint32_t position) const {
  const std::uint32_t slot = slot_of(change_log_[position]);
  return slot != npos && log_position_[slot] == position;
}

void SparseSet::collect_changed_since(Tick since, std::vector<Entity>& out) const {
  const auto first = std::upper_bound(
      segments_.begin(), segments_.end(), since,
      [](Tick value, const Segment& segment) { return value < segment.tick; });
  if (first == segments_.end()) return;
  for (auto position = first->begin; position < change_log_.size(); ++position) {
    if (is_newest_entry(position)) out.push_back(change_log_[position]);
  }
}

void SparseSet::compact_change_log() {
  std::uint32_t kept = 0;
  std::size_t segments_kept = 0;
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const std::uint32_t end =
        s + 1 < segments_.size() ? segments_[s + 1].begin
                                 : static_cast<std::uint32_t>(change_log_.size());
    const std::uint32_t new_begin = kept;
    for (std::uint32_t position = segments_[s].begin; position < end; ++position) {
      if (!is_newest_entry(position)) continue;
      const Entity entity = change_log_[position];
      log_position_[slot_of(entity)] = kept;
      change_log_[kept++] = entity;
    }
    if (kept != new_begin) segments_[segments_kept++] = Segment{segments_[s].tick, new_begin};
  }
  change_log_.resize(kept);
  segments_.resize(segments_kept);
}

std::span<const Removal> SparseSet::removed_since(Tick since) const {
  const auto first = std::upper_bound(
      removals_.begin(), removals_.end(), since,
      [](Tick value, const Removal& removal) { return value < removal.tick; });
  return {first, removals_.end()};
}

void SparseSet::forget_removals_before(Tick tick) {
  const auto first_kept = std::lower_bound(
      removals_.begin(), removals_.end(), tick,
      [](const Removal& removal, Tick value) { return removal.tick < value; });
  removals_.erase(removals_.begin(), first_kept);
}

std::uint32_t SparseSet::insert(Entity entity, Tick now) {
  if (entity.index >= sparse_.size()) sparse_.resize(entity.index + std::size_t{1}, npos);
  begin_changes(now);
  const auto slot = static_cast<std::uint32_t>(dense_.size());
  sparse_[entity.index] = slot;
  dense_.push_back(entity);
  log_position_.push_back(static_cast<std::uint32_t>(change_log_.size()));
  change_log_.push_back(entity);
  return slot;
}

void SparseSet::erase(std::uint32_t slot, Tick now) {
  const Entity removed = dense_[slot];
  const Entity last = dense_.back();
  dense_[slot] = last;
  log_position_[slot] = log_position_.back();
  sparse_[last.index] = slot;
  dense_.pop_back();
  log_position_.pop_back();
  removals_.push_back(Removal{removed, now});
}

}  // namespace sg::ecs
