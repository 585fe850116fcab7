// SPDX-License-Identifier: MIT
// The frame-time budget for shadows against a model of GPU time: the real atlas planner sizes
// the tiles from the budget's limits, a frame's shadow passes take
// ms = per_view * views + per_texel * texels drawn (with noise), and each measurement comes back
// frames in flight late, as from the GPU. The planner learns which maps are redrawn as the
// schedule tells it (ShadowAtlasPlanner::record_redraws).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <random>
#include <string>
#include <vector>

#include "systems/shadows/shadow_atlas_planner.h"
#include "systems/shadows/shadow_time_budget.h"

namespace sg::shadows {
namespace {

constexpr double budget_ms = 6.0;

// Moving lights of one 2D map each: every view is due every frame.
class ShadowLoop {
 public:
  explicit ShadowLoop(double budget = budget_ms, double noise = 0.05,
                      ShadowTimePolicy policy = ShadowTimePolicy::redraw_cost)
      : budget_(budget),
        noise_(noise),
        planner_({.page_size = 4096, .max_pages = 256, .min_resolution = 16}, policy) {}

  // `count` lights whose importances spread evenly in log2 over [low, high], each with a
  // quality floor of 64 texels.
  void set_lights(uint32_t count, float low = 32.0f, float high = 1024.0f) {
    importance_.clear();
    for (uint32_t i = 0; i < count; ++i) {
      importance_.push_back(low *
                            std::exp2(std::log2(high / low) * float(i) / float(std::max(count - 1, 1u))));
    }
  }
  // Lights that stand still: nothing is due but maps whose tiles changed.
  void set_moving(bool moving) { moving_ = moving; }
  // Every `every`-th light (0: none) stands still while the others move.
  void set_still_every(uint32_t every) { still_every_ = every; }
  bool still(size_t light) const { return !moving_ || (still_every_ != 0 && light % still_every_ == 0); }

  struct Frame {
    double ms = 0.0;  // this frame's shadow passes
    ShadowTimeBudget::Limits limits;
  };
  Frame frame() {
    const ShadowTimeBudget::Limits limits = budget_.limits();
    const uint64_t step = budget_.step();
    requests_.clear();
    std::uniform_real_distribution<float> wander(-0.1f, 0.1f);  // lights move: importances jitter
    for (size_t i = 0; i < importance_.size(); ++i) {
      const float jitter = still(i) ? 1.0f : std::exp2(wander(random_));
      requests_.push_back({.key = i, .importance = importance_[i] * jitter, .quality_floor = 64});
    }
    placements_.assign(requests_.size(), {});
    planner_.plan(requests_, placements_, nullptr, limits.lowered_tiers);
    // Due: the moving lights' maps, and still ones in new tiles.
    uint32_t due = 0;
    uint64_t due_texels = 0;
    redraws_.assign(requests_.size(), ShadowAtlasPlanner::map_redrawn);
    for (size_t i = 0; i < placements_.size(); ++i) {
      const ShadowPlacement& placement = placements_[i];
      if (still(i))
        redraws_[i] = placement.moved ? ShadowAtlasPlanner::no_redraw_sample : ShadowAtlasPlanner::map_kept;
      if (!still(i) || placement.moved) {
        ++due;
        due_texels += uint64_t{placement.resolution} * placement.resolution;
      }
    }
    planner_.record_redraws(redraws_);
    const uint32_t drawn = limits.view_cap == 0 ? due : std::min(due, limits.view_cap);
    // Capped views come round in turn (ShadowCache): on average each costs the mean texels.
    const double drawn_texels = due == 0 ? 0.0 : double(due_texels) * drawn / due;
    std::uniform_real_distribution<double> noise(1.0 - noise_, 1.0 + noise_);
    const double ms = (per_view_ms * drawn + per_texel_ms * drawn_texels) * noise(random_);
    const AtlasStats& stats = planner_.stats();
    budget_.planned({stats.lowerable_by_time, due, stats.demoted_by_time, due - drawn});
    in_flight_.push_back({step, drawn, ms});
    if (in_flight_.size() > frames_in_flight) {
      const Measured late = in_flight_.front();
      in_flight_.pop_front();
      budget_.measured(late.step, late.views, late.ms);
    }
    return {ms, limits};
  }
  // frame() `count` times: the frames' results.
  std::vector<Frame> frames(int count) {
    std::vector<Frame> out;
    for (int i = 0; i < count; ++i) out.push_back(frame());
    return out;
  }

  ShadowTimeBudget& budget() { return budget_; }
  // The last frame's, per light.
  const std::vector<ShadowPlacement>& placements() const { return placements_; }
  float importance(size_t light) const { return importance_[light]; }

  static constexpr double per_view_ms = 0.002;
  static constexpr double per_texel_ms = 0.5e-6;
  static constexpr size_t frames_in_flight = 2;

 private:
  struct Measured {
    uint64_t step = 0;
    uint32_t views = 0;
    double ms = 0.0;
  };
  ShadowTimeBudget budget_;
  double noise_;
  ShadowAtlasPlanner planner_;  // memory never binds
  std::vector<float> importance_;
  bool moving_ = true;
  uint32_t still_every_ = 0;
  std::vector<ShadowRequest> requests_;
  std::vector<uint8_t> redraws_;
  std::vector<ShadowPlacement> placements_;
  std::deque<Measured> in_flight_;
  std::mt19937 random_{7};
};

// The first frame from `from` on whose measurement and the next ten are within the budget; -1
// if none.
int settled_at(const std::vector<ShadowLoop::Frame>& frames, size_t from = 0, double budget = budget_ms) {
  for (size_t i = from; i + 10 < frames.size(); ++i) {
    if (std::all_of(frames.begin() + i, frames.begin() + i + 11,
                    [&](const ShadowLoop::Frame& f) { return f.ms <= budget; })) {
      return static_cast<int>(i - from);
    }
  }
  return -1;
}

// How often the limits changed from frame to frame within [from, to).
int changes(const std::vector<ShadowLoop::Frame>& frames, size_t from, size_t to) {
  int count = 0;
  for (size_t i = from + 1; i < to; ++i) count += frames[i].limits != frames[i - 1].limits;
  return count;
}

TEST(ShadowTimeBudget, OffLeavesTheLimitsAlone) {
  ShadowLoop loop(0.0);
  loop.set_lights(256);
  const std::vector<ShadowLoop::Frame> frames = loop.frames(60);
  EXPECT_GT(frames.back().ms, 3 * budget_ms) << "the load is heavy";
  for (const ShadowLoop::Frame& frame : frames) EXPECT_EQ(frame.limits, ShadowTimeBudget::Limits{});
  EXPECT_FALSE(loop.budget().on());
  EXPECT_EQ(loop.budget().step(), 0u);
  EXPECT_FALSE(loop.budget().take_message());
}

// A load nearly four times the budget at full quality: lowered tiers bring it under at the first
// decision (its three frames measured two frames late), and the limits then hold still.
TEST(ShadowTimeBudget, TiersConvergeUnderTheBudgetAndStayThere) {
  ShadowLoop loop;
  loop.set_lights(256);
  const std::vector<ShadowLoop::Frame> frames = loop.frames(1000);
  EXPECT_GT(frames.front().ms, 3 * budget_ms) << "full quality is over the budget";
  const int settled = settled_at(frames);
  ASSERT_GE(settled, 0);
  EXPECT_LE(settled, 10) << "frames to converge";
  EXPECT_GT(frames[settled].limits.lowered_tiers, 0.0f);
  EXPECT_EQ(frames[settled].limits.view_cap, 0u) << "tiers suffice: no view waits";
  EXPECT_LE(changes(frames, settled, frames.size()), 2);
  EXPECT_TRUE(std::all_of(frames.begin() + settled, frames.end(),
                          [](const ShadowLoop::Frame& f) { return f.ms <= budget_ms; }));
  EXPECT_GT(frames.back().ms, 0.5 * budget_ms) << "not much tighter than it needs";
}

// Six large lights: a tier of one of them is a large part of the frame, far from the smooth
// model the steps are sized by, so a relax may overshoot. Each that does is undone, and the next
// waits twice as long: the limits change less and less often.
TEST(ShadowTimeBudget, AFewLargeLightsConvergeAndProbeLessAndLessOften) {
  for (const double budget : {1.0, 2.0, 3.0, 4.0}) {
    ShadowLoop loop(budget);
    loop.set_lights(6, 600.0f, 2048.0f);
    const std::vector<ShadowLoop::Frame> frames = loop.frames(2000);
    EXPECT_GT(frames.front().ms, 1.3 * budget);
    const int settled = settled_at(frames, 0, budget);
    ASSERT_GE(settled, 0) << budget << " ms";
    EXPECT_LE(settled, 15) << budget << " ms";
    // Holds of 30, 60, ... 960 frames: at most two changes in each.
    EXPECT_LE(changes(frames, settled, 1000), 12) << budget << " ms";
    EXPECT_LE(changes(frames, 1000, frames.size()), 3) << budget << " ms";
    const auto over = std::count_if(frames.begin() + settled, frames.end(),
                                    [&](const ShadowLoop::Frame& f) { return f.ms > budget; });
    EXPECT_LE(over, 50) << budget << " ms";
  }
}

TEST(ShadowTimeBudget, AStepInLoadRecoversInAFewFrames) {
  ShadowLoop loop;
  loop.set_lights(256);
  std::vector<ShadowLoop::Frame> frames = loop.frames(300);
  ASSERT_GE(settled_at(frames, 250), 0);
  loop.set_lights(1024);  // four times the lights
  const std::vector<ShadowLoop::Frame> after = loop.frames(300);
  EXPECT_GT(after.front().ms, 2.5 * budget_ms);
  const int recovered = settled_at(after);
  ASSERT_GE(recovered, 0);
  EXPECT_LE(recovered, 15) << "frames to get back under the budget";
  EXPECT_LE(changes(after, recovered, after.size()), 2);
}

TEST(ShadowTimeBudget, RemovingTheLoadRelaxesToFullQuality) {
  ShadowLoop loop;
  loop.set_lights(1024);
  const std::vector<ShadowLoop::Frame> loaded = loop.frames(300);
  ASSERT_GT(loaded.back().limits.lowered_tiers, 1.0f);
  loop.set_lights(16);  // a light load: full quality fits
  const std::vector<ShadowLoop::Frame> light = loop.frames(300);
  const auto full = std::find_if(light.begin(), light.end(), [](const ShadowLoop::Frame& f) {
    return f.limits == ShadowTimeBudget::Limits{};
  });
  ASSERT_NE(full, light.end());
  EXPECT_LE(full - light.begin(), 60) << "frames to relax";
  EXPECT_EQ(changes(light, full - light.begin(), light.size()), 0);

  // Lights that stop moving draw nothing: full quality again too.
  loop.set_lights(1024);
  ASSERT_GT(loop.frames(300).back().limits.lowered_tiers, 1.0f);
  loop.set_moving(false);
  EXPECT_EQ(loop.frames(100).back().limits, ShadowTimeBudget::Limits{});
}

// Half the lights stand still: drawn once, their maps cost no time after. Under redraw_cost the
// budget's tiers fall on the moving half and the still half climbs back to what its size asks;
// uniform lowers both halves alike for about the same time.
TEST(ShadowTimeBudget, RedrawCostSparesTheMapsOfLightsThatStandStill) {
  // Mean log2(resolution / what its importance asks) over the still or the moving lights.
  const auto tiers_lowered = [](const ShadowLoop& loop, bool still) {
    double sum = 0.0;
    int count = 0;
    for (size_t i = 0; i < loop.placements().size(); ++i) {
      if (loop.still(i) != still || loop.importance(i) < 128.0f) continue;  // above the floor
      const float asks = std::exp2(std::round(std::log2(loop.importance(i))));
      sum += std::log2(asks / float(loop.placements()[i].resolution));
      ++count;
    }
    return sum / count;
  };
  struct Outcome {
    double still = 0.0, moving = 0.0, ms = 0.0;
  };
  const auto run = [&](ShadowTimePolicy policy) {
    ShadowLoop loop(budget_ms, 0.05, policy);
    loop.set_lights(512);
    loop.set_still_every(2);
    const std::vector<ShadowLoop::Frame> frames = loop.frames(600);
    EXPECT_GE(settled_at(frames, 300), 0) << "within the budget";
    return Outcome{tiers_lowered(loop, true), tiers_lowered(loop, false), frames.back().ms};
  };
  const Outcome cost = run(ShadowTimePolicy::redraw_cost);
  const Outcome uniform = run(ShadowTimePolicy::uniform);
  EXPECT_GT(uniform.still, 0.75) << "uniform lowers the still lights";
  EXPECT_NEAR(uniform.still, uniform.moving, 0.25) << "as much as the moving ones";
  EXPECT_LT(cost.still, 0.25) << "redraw_cost leaves them at what their size asks";
  EXPECT_LT(cost.moving, uniform.moving + 0.25) << "and lowers the moving ones no more";
  EXPECT_GT(cost.ms, 0.5 * budget_ms) << "for about the same time";
  EXPECT_GT(uniform.ms, 0.5 * budget_ms);
}

// Lights all at their quality floor: lower tiers gain nothing, so views wait their turn.
TEST(ShadowTimeBudget, WhenNoLightIsAboveItsFloorViewsAreCapped) {
  ShadowLoop loop;
  loop.set_lights(8192, 40.0f, 64.0f);  // 8192 views of 32 or 64 texels: 16 ms + 14 ms
  const std::vector<ShadowLoop::Frame> frames = loop.frames(400);
  EXPECT_GT(frames.front().ms, 4 * budget_ms);
  const int settled = settled_at(frames);
  ASSERT_GE(settled, 0);
  EXPECT_LE(settled, 10);
  EXPECT_EQ(frames.back().limits.lowered_tiers, 0.0f) << "no light was above its floor";
  EXPECT_GT(frames.back().limits.view_cap, 1000u);
  EXPECT_LT(frames.back().limits.view_cap, 8192u);
  EXPECT_LE(changes(frames, settled, frames.size()), 2);

  loop.set_lights(64, 40.0f, 64.0f);
  EXPECT_EQ(loop.frames(100).back().limits, ShadowTimeBudget::Limits{})
      << "the cap goes once it covers the views due";
}

// A budget nothing can meet: every light at its floor, min_view_cap views a frame, each light
// still drawn in turn.
TEST(ShadowTimeBudget, ABudgetBeyondReachStopsAtTheFloorsAndTheSmallestCap) {
  ShadowLoop loop(0.001);
  loop.set_lights(256);
  const std::vector<ShadowLoop::Frame> frames = loop.frames(400);
  EXPECT_EQ(frames.back().limits.view_cap, ShadowTimeBudget::min_view_cap);
  EXPECT_GT(frames.back().limits.lowered_tiers, 0.0f);
  EXPECT_LT(frames.back().limits.lowered_tiers, ShadowTimeBudget::max_lowered_tiers)
      << "tiers stop rising once every light is at its floor";
  EXPECT_GT(frames.back().ms, 0.0);
}

TEST(ShadowTimeBudget, OnlyFramesPlannedWithTheCurrentLimitsCount) {
  ShadowTimeBudget budget(budget_ms);
  budget.planned({.lights_lowerable = 10, .views_uncapped = 100});
  const uint64_t first = budget.step();
  for (uint32_t i = 0; i < ShadowTimeBudget::samples_per_decision; ++i)
    budget.measured(first, 100, 3.9 * 0.9 * budget_ms);
  // About four times the aim: log4(3.9) rounded up to tier steps, one tier.
  EXPECT_EQ(budget.limits().lowered_tiers, 1.0f);
  EXPECT_NE(budget.step(), first);
  // Frames planned before the change come back late, as slow: they are not news.
  for (int i = 0; i < 30; ++i) budget.measured(first, 100, 100.0);
  EXPECT_EQ(budget.limits().lowered_tiers, 1.0f);
  // Two frames of the new step are not enough to decide on.
  budget.measured(budget.step(), 100, 100.0);
  budget.measured(budget.step(), 100, 100.0);
  EXPECT_EQ(budget.limits().lowered_tiers, 1.0f);
  budget.measured(budget.step(), 100, 100.0);
  EXPECT_EQ(budget.limits().lowered_tiers, 1.0f + ShadowTimeBudget::max_tier_step);
}

TEST(ShadowTimeBudget, OneSlowFrameOfThreeDoesNotDecide) {
  ShadowTimeBudget budget(budget_ms);
  budget.planned({.lights_lowerable = 10, .views_uncapped = 100});
  budget.measured(0, 100, 5.0);
  budget.measured(0, 100, 50.0);  // e.g. every tile the last change moved, redrawn at once
  budget.measured(0, 100, 5.5);
  EXPECT_EQ(budget.limits(), ShadowTimeBudget::Limits{});
  EXPECT_EQ(budget.decided_on_ms(), 5.5);
}

// A relax the frames after it find over the budget goes back to the limits before it (the
// planner turns them into the same resolutions), and the next relax waits twice as long.
TEST(ShadowTimeBudget, ARelaxThatOvershootsIsUndoneAndTheNextWaitsLonger) {
  ShadowTimeBudget budget(budget_ms);
  budget.planned({.lights_lowerable = 10, .views_uncapped = 100});
  const auto measure = [&](uint32_t frames, double ms) {
    for (uint32_t i = 0; i < frames; ++i) budget.measured(budget.step(), 100, ms);
  };
  measure(3, 22.0);  // log4(22 / 5.4) = 1.01 tiers, in quarter tiers up
  ASSERT_EQ(budget.limits().lowered_tiers, 1.25f);
  // Half the budget: a quarter tier up stays under relax_below in the model, but not before
  // min_relax_hold frames.
  measure(ShadowTimeBudget::min_relax_hold - 3, 3.0);
  EXPECT_EQ(budget.limits().lowered_tiers, 1.25f);
  measure(3, 3.0);
  ASSERT_EQ(budget.limits().lowered_tiers, 1.0f);
  measure(3, 7.0);  // it was not
  EXPECT_EQ(budget.limits().lowered_tiers, 1.25f);
  measure(ShadowTimeBudget::min_relax_hold, 3.0);
  EXPECT_EQ(budget.limits().lowered_tiers, 1.25f) << "the next relax waits twice as long";
  measure(ShadowTimeBudget::min_relax_hold, 3.0);
  EXPECT_EQ(budget.limits().lowered_tiers, 1.0f);
}

TEST(ShadowTimeBudget, MessagesSayWhatTheBudgetHoldsDownAndAreRateLimited) {
  ShadowTimeBudget budget(budget_ms);
  budget.planned({});
  EXPECT_FALSE(budget.take_message()) << "nothing held down";
  budget.planned({.lights_lowerable = 10, .views_uncapped = 100, .lights_demoted = 7, .views_deferred = 40});
  const std::optional<std::string> line = budget.take_message();
  ASSERT_TRUE(line);
  EXPECT_NE(line->find("7 lights below"), std::string::npos) << *line;
  EXPECT_NE(line->find("40 views deferred"), std::string::npos) << *line;
  int lines = 0;
  for (uint32_t frame = 1; frame < ShadowTimeBudget::message_interval; ++frame) {
    budget.planned({.lights_demoted = 7 + frame});
    lines += budget.take_message().has_value();
  }
  EXPECT_EQ(lines, 0);
  budget.planned({});
  const std::optional<std::string> restored = budget.take_message();
  ASSERT_TRUE(restored);
  EXPECT_NE(restored->find("every light at the resolution its size asks"), std::string::npos) << *restored;
}

}  // namespace
}  // namespace sg::shadows
