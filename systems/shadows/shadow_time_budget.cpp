// SPDX-License-Identifier: MIT
#include "systems/shadows/shadow_time_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sg::shadows {
namespace {

// log4(ratio): the tiers that scale texels by `ratio`, in whole tier_steps (rounded up or down),
// at most max_tier_step.
float tiers_for(double ratio, bool round_up) {
  const double steps = 0.5 * std::log2(ratio) / ShadowTimeBudget::tier_step;
  const double whole = round_up ? std::ceil(steps) : std::floor(steps);
  return std::clamp(float(whole) * ShadowTimeBudget::tier_step, 0.0f, ShadowTimeBudget::max_tier_step);
}

}  // namespace

ShadowTimeBudget::ShadowTimeBudget(double budget_ms) : budget_ms_(budget_ms > 0.0 ? budget_ms : 0.0) {}

void ShadowTimeBudget::planned(const Plan& plan) {
  plan_ = plan;
  ++frames_planned_;
}

void ShadowTimeBudget::measured(uint64_t step, uint32_t views, double ms) {
  if (!on()) return;
  ++measured_frames_;
  if (step != step_) return;  // planned before the last change
  samples_.push_back({std::max(ms, 0.0), views});
  if (samples_.size() < samples_per_decision) return;
  const auto middle = samples_.begin() + samples_.size() / 2;
  std::nth_element(samples_.begin(), middle, samples_.end(),
                   [](const Sample& a, const Sample& b) { return a.ms < b.ms; });
  const Sample median = *middle;
  samples_.clear();
  decided_on_ms_ = median.ms;
  // Far below, where even a whole tier up would stay under relax_below, the load went: no long
  // hold.
  const uint64_t hold = 4.0 * median.ms < relax_below * budget_ms_ ? min_relax_hold : relax_hold_;
  if (median.ms > budget_ms_) {
    tighten(median);
  } else if (median.ms < relax_below * budget_ms_ && measured_frames_ - last_change_frame_ >= hold) {
    relax(median);
  }
}

void ShadowTimeBudget::tighten(const Sample& sample) {
  // Over the budget within a hold of a relax: the relax overshot. Its limits held the frames
  // before, and the planner gives the same resolutions for the same limits: back to them, and
  // wait longer before the next relax.
  if (last_change_ == Change::relax && measured_frames_ - last_change_frame_ < relax_hold_) {
    relax_hold_ = std::min(2 * relax_hold_, max_relax_hold);
    limits_ = before_relax_;
    changed(Change::tighten);
    return;
  }
  const double ratio = sample.ms / (target_fraction * budget_ms_);
  Limits next = limits_;
  if (plan_.lights_lowerable > 0 && next.lowered_tiers < max_lowered_tiers) {
    next.lowered_tiers =
        std::min(max_lowered_tiers, next.lowered_tiers + std::max(tier_step, tiers_for(ratio, true)));
  } else {
    // Views cost about the same each: the cap scales with the time.
    const auto cap = std::max(min_view_cap, static_cast<uint32_t>(double(sample.views) / ratio));
    if (cap < sample.views) next.view_cap = next.view_cap == 0 ? cap : std::min(cap, next.view_cap);
  }
  if (next == limits_) return;  // nothing left to lower: the budget cannot be met
  limits_ = next;
  changed(Change::tighten);
}

void ShadowTimeBudget::relax(const Sample& sample) {
  const double ratio = relax_below * budget_ms_ / sample.ms;  // > 1, infinite for no time at all
  Limits next = limits_;
  if (next.view_cap != 0) {
    const double grown = std::ceil(double(next.view_cap) * std::min(ratio, 2.0));
    next.view_cap = grown >= double(plan_.views_uncapped) ? 0 : static_cast<uint32_t>(grown);
  } else if (next.lowered_tiers > 0.0f) {
    next.lowered_tiers = std::max(0.0f, next.lowered_tiers - tiers_for(ratio, false));
  }
  if (next == limits_) return;  // at full quality
  if (last_change_ == Change::relax) relax_hold_ = std::max(relax_hold_ / 2, min_relax_hold);
  before_relax_ = limits_;
  limits_ = next;
  changed(Change::relax);
}

void ShadowTimeBudget::changed(Change change) {
  ++step_;
  samples_.clear();
  last_change_frame_ = measured_frames_;
  last_change_ = change;
}

std::optional<std::string> ShadowTimeBudget::take_message() {
  if (!on()) return std::nullopt;
  const Effect effect{plan_.lights_demoted, plan_.views_deferred};
  const std::optional<Effect> was = report_.due(effect, frames_planned_);
  if (!was) return std::nullopt;
  char line[320];
  const double measured = decided_on_ms_.value_or(0.0);
  if (effect == Effect{}) {
    std::snprintf(line, sizeof(line),
                  "shadow time budget (%.2f ms, shadow passes %.2f ms): every light at the resolution its "
                  "size asks and every view due drawn again (was %u lower, %u deferred)",
                  budget_ms_, measured, was->demoted, was->deferred);
  } else {
    std::snprintf(line, sizeof(line),
                  "shadow time budget (%.2f ms, shadow passes %.2f ms): %u lights below the resolution their "
                  "size asks (%.2f tiers lower), %u views deferred (was %u lower, %u deferred)",
                  budget_ms_, measured, effect.demoted, double(limits_.lowered_tiers), effect.deferred,
                  was->demoted, was->deferred);
  }
  return std::string(line);
}

}  // namespace sg::shadows
