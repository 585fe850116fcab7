#include "ecs/sparse_set.h"

#include <algorithm>

namespace sg::ecs {

namespace {
// Small pools are not worth compacting often; this also keeps tiny pools from compacting on
// every tick.
constexpr std::size_t min_log_size_before_compaction = 1024;
}  // namespace

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

std::uint64_t SparseSet::begin_changes(Tick now) {
  if (!segments_.empty() && segments_.back().tick == now) return segments_.back().begin;
  if (change_log_.size() > 2 * dense_.size() + min_log_size_before_compaction) {
    compact_change_log();
  }
  segments_.push_back(Segment{now, end_of_log()});
  return segments_.back().begin;
}

void SparseSet::mark_all_changed(Tick now) {
  bulk_tick_ = now;
  log_base_ = end_of_log();
  change_log_.clear();
  segments_.clear();
}

Tick SparseSet::change_tick(std::uint32_t slot) const {
  const std::uint64_t position = log_position_[slot];
  if (position < log_base_) return bulk_tick_;
  const auto after =
      std::upper_bound(segments_.begin(), segments_.end(), position,
                       [](std::uint64_t value, const Segment& segment) { return value < segment.begin; });
  return std::prev(after)->tick;
}

bool SparseSet::is_newest_entry(std::uint64_t position) const {
  const std::uint32_t slot = slot_of(change_log_[position - log_base_]);
  return slot != npos && log_position_[slot] == position;
}

void SparseSet::collect_changed_since(Tick since, std::vector<Entity>& out) const {
  if (bulk_tick_ > since) {
    // Everything present at the bulk mark changed then, and everything added since is newer.
    out.insert(out.end(), dense_.begin(), dense_.end());
    return;
  }
  const auto first =
      std::upper_bound(segments_.begin(), segments_.end(), since,
                       [](Tick value, const Segment& segment) { return value < segment.tick; });
  if (first == segments_.end()) return;
  for (auto position = first->begin; position < end_of_log(); ++position) {
    if (is_newest_entry(position)) out.push_back(change_log_[position - log_base_]);
  }
}

void SparseSet::compact_change_log() {
  std::size_t kept = 0;
  std::size_t segments_kept = 0;
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const std::uint64_t end = s + 1 < segments_.size() ? segments_[s + 1].begin : end_of_log();
    const std::uint64_t new_begin = log_base_ + kept;
    for (std::uint64_t position = segments_[s].begin; position < end; ++position) {
      if (!is_newest_entry(position)) continue;
      const Entity entity = change_log_[position - log_base_];
      log_position_[slot_of(entity)] = log_base_ + kept;
      change_log_[kept++] = entity;
    }
    if (log_base_ + kept != new_begin) {
      segments_[segments_kept++] = Segment{segments_[s].tick, new_begin};
    }
  }
  change_log_.resize(kept);
  segments_.resize(segments_kept);
}

std::span<const Removal> SparseSet::removed_since(Tick since) const {
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
  begin_changes(now);
  const auto slot = static_cast<std::uint32_t>(dense_.size());
  sparse_[entity.index] = slot;
  dense_.push_back(entity);
  log_position_.push_back(end_of_log());
  change_log_.push_back(entity);
  ++layout_version_;
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
  ++layout_version_;
}

}  // namespace sg::ecs
