// SPDX-License-Identifier: MIT
#include "systems/shadows/caster_changes.h"

#include <utility>

namespace sg::shadows {

std::span<const scene::Aabb> CasterChangeTracker::update(std::span<const CasterBounds> casters) {
  changes_.clear();
  current_indices_.clear();
  ++frame_;
  // Frames count from 1, so a slot's frame of 0 means "never seen", not "seen in frame 0".
  const auto in_previous_frame = [&](const Slot& slot) {
    return slot.frame != 0 && slot.frame + 1 == frame_;
  };

  for (const CasterBounds& caster : casters) {
    const auto index = static_cast<uint32_t>(caster.key);
    const auto generation = static_cast<uint32_t>(caster.key >> 32);
    if (index >= slots_.size()) slots_.resize(size_t{index} + 1);
    Slot& slot = slots_[index];
    if (in_previous_frame(slot) && slot.generation == generation) {
      if (slot.bounds.min != caster.bounds.min || slot.bounds.max != caster.bounds.max) {
        report(slot.bounds);
        report(caster.bounds);
      } else if (slot.layers != caster.layers) {
        report(caster.bounds);
      }
    } else {
      // The slot's previous caster was destroyed and the slot reused within one frame: the old
      // caster is gone as surely as if its slot had stayed empty.
      if (in_previous_frame(slot)) report(slot.bounds);
      report(caster.bounds);
    }
    slot = {generation, frame_, caster.bounds, caster.layers};
    current_indices_.push_back(index);
  }

  for (const uint32_t index : previous_indices_) {
    if (slots_[index].frame != frame_) report(slots_[index].bounds);
  }
  std::swap(previous_indices_, current_indices_);
  return changes_;
}

void CasterChangeTracker::report(const scene::Aabb& box) {
  // The first frame has nothing to compare with (see the header).
  if (frame_ > 1 && !box.empty()) changes_.push_back(box);
}

}  // namespace sg::shadows
