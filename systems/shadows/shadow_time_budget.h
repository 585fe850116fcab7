// SPDX-License-Identifier: MIT
#pragma once
// The frame-time budget for shadows (--shadow-budget-ms): from the GPU time the shadow passes of
// recent frames measured, how far the schedule lowers the lights' resolutions and how many views
// it redraws a frame at most (Limits, which ShadowSchedule applies). The memory budget (the
// atlas planner's) stays a second cap on top.
//
// - Two knobs, in this order. Resolution first: `lowered_tiers`, by which the planner lowers log2
//   of every light's resolution before its rounding (ShadowAtlasPlanner::plan: importances
//   followed with a backlash, so that they neither pop nor keep a step from being undone; never
//   below a light's quality floor), so every map keeps in proportion to its light's size on
//   screen and the smallest, least important lights reach their floor and stop first. A uniform
//   offset rather than the memory budget's demotions from the least important up: those save
//   little time per light demoted (time goes with texels, which the large maps hold), and a light
//   whose importance crosses another's would pop between tiers frame after frame. Once no light
//   is above its floor (Plan::lights_lowerable), views: `view_cap`, the views redrawn a frame at
//   most; ShadowCache defers the rest stalest first, so every view due comes round. No light
//   loses its shadow to time. Relaxing undoes them in reverse: the cap first (gone once it
//   covers the views due), then the tiers.
// - Late measurements: a frame's times come back frames in flight after it was planned, and a
//   frame planned before the last change says nothing about it. Each change starts a new step();
//   a frame hands back the step it was planned with (measured()) and only the current step's
//   frames count. It decides on the median of samples_per_decision of them, so one frame that
//   redrew every tile the last change moved does not decide.
// - Dead band: over the budget it tightens; under relax_below of it, it may relax; in between it
//   holds. Steps are in log2, sized by the measured ratio: texels go as 4^-tiers, so a frame
//   `r` times over target_fraction of the budget lowers by log4(r) tiers, rounded up to
//   tier_step, at most max_tier_step at once. Relaxing raises by log4 of how far under
//   relax_below it is, rounded down: in that model a relax stays under relax_below, and no tier
//   relaxes while a quarter tier more would leave it (above relax_below / 4^tier_step, about
//   0.57 of the budget). A view cap grows by the same ratio, at most twice, and goes once it
//   covers the views due.
// - No oscillation: a relax waits relax_hold measured frames after any change. Over the budget
//   within relax_hold frames of a relax, the relax overshot (a few large lights going up a tier
//   cost more than the model says): the limits go back to those before it, which the planner
//   turns into the same resolutions, and the next relax waits twice as long, up to
//   max_relax_hold; a relax that held halves the wait again, down to min_relax_hold. After
//   convergence the limits change at most twice per hold, and the hold grows while relaxes fail.
//   Under a quarter of relax_below (a whole tier more would not reach it) the load went: relaxes
//   wait min_relax_hold only.
//
// Plain data, no GPU: tests/systems/shadows/shadow_time_budget_test.cpp drives it with a model
// of GPU time.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "systems/shadows/budget_report.h"

namespace sg::shadows {

class ShadowTimeBudget {
 public:
  struct Limits {
    float lowered_tiers = 0.0f;  // ShadowAtlasPlanner::plan's
    uint32_t view_cap = 0;       // views redrawn a frame at most; 0: no cap
    friend bool operator==(const Limits&, const Limits&) = default;
  };
  // What the schedule made of limits() in the frame it planned with them.
  struct Plan {
    uint32_t lights_lowerable = 0;  // above their quality floor (AtlasStats::lowerable_by_time)
    uint32_t views_uncapped = 0;    // views due the frame would have drawn without view_cap
    uint32_t lights_demoted = 0;    // below what their size asks (AtlasStats::demoted_by_time)
    uint32_t views_deferred = 0;    // views_uncapped less the views drawn
  };

  static constexpr uint32_t samples_per_decision = 3;
  static constexpr double target_fraction = 0.9;  // tightening aims here, inside the dead band
  static constexpr double relax_below = 0.8;
  static constexpr float tier_step = 0.25f;
  static constexpr float max_tier_step = 2.0f;
  // More than any atlas has: page_size / min_resolution <= 1024.
  static constexpr float max_lowered_tiers = 10.0f;
  static constexpr uint32_t min_view_cap = 6;     // a point light's six faces
  static constexpr uint64_t min_relax_hold = 30;  // measured frames
  static constexpr uint64_t max_relax_hold = 960;
  static constexpr uint64_t message_interval = 60;  // frames planned between log lines, at most one

  // `budget_ms`: the shadow passes' GPU time a frame may take; 0 (or less): no budget, limits()
  // stay none.
  explicit ShadowTimeBudget(double budget_ms = 0.0);

  bool on() const { return budget_ms_ > 0.0; }
  double budget_ms() const { return budget_ms_; }
  // For the next frame planned.
  const Limits& limits() const { return limits_; }
  // Which limits() a frame is planned with: the frame hands it back with its times.
  uint64_t step() const { return step_; }
  // The median the last decision was taken on; unset before the first.
  std::optional<double> decided_on_ms() const { return decided_on_ms_; }

  // The frame just planned with limits() came out as `plan`.
  void planned(const Plan& plan);
  // The shadow passes of a frame planned at `step` drew `views` views in `ms` of GPU time.
  void measured(uint64_t step, uint32_t views, double ms);

  // A line for the log when the budget's effect on the frames planned (lights demoted, views
  // deferred) differs from the last line's, at most one every message_interval frames; else
  // nullopt.
  std::optional<std::string> take_message();

 private:
  struct Sample {
    double ms = 0.0;
    uint32_t views = 0;
  };
  enum class Change { none, tighten, relax };
  void tighten(const Sample& sample);
  void relax(const Sample& sample);
  void changed(Change change);

  double budget_ms_;
  Limits limits_;
  uint64_t step_ = 0;
  Plan plan_;
  std::vector<Sample> samples_;  // of the current step
  std::optional<double> decided_on_ms_;
  uint64_t measured_frames_ = 0;
  uint64_t last_change_frame_ = 0;  // measured_frames_ then
  Change last_change_ = Change::none;
  Limits before_relax_;  // the limits the last relax loosened
  uint64_t relax_hold_ = min_relax_hold;

  struct Effect {
    uint32_t demoted = 0;
    uint32_t deferred = 0;
    friend bool operator==(const Effect&, const Effect&) = default;
  };
  uint64_t frames_planned_ = 0;
  BudgetReport<Effect> report_{message_interval};
};

}  // namespace sg::shadows
