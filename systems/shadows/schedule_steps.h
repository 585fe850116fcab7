// SPDX-License-Identifier: MIT
#pragma once
// How long each step of one ShadowSchedule::schedule took: where the CPU frame goes with
// thousands of lights, for shadowgraph-light-bench and the sandbox's --stats. A dozen clock reads
// a frame.
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace sg::shadows {

enum class ScheduleStep : uint8_t {
  views,       // every view's importance, its request and what the cache sees of it
  requests,    // the views in sight listed as the atlas plan's requests
  match,       // atlas plan: each request's light found, its wanted resolution
  budget,      // atlas plan: the memory budget's demotions
  tiles,       // atlas plan: tiles for the lights whose resolution or kind changed
  placements,  // atlas plan: the placements written and counted
  dirty,       // shadow cache: the maps their lights made wrong
  casters,     // shadow cache: the maps changed casters reach
  choose,      // shadow cache: the maps redrawn within the view budget
  renders,     // shadow cache: how each is drawn, what is usable, the counts and lags
  apply,       // the tiles and renders onto the views and their records, the redraw rates
  count
};
inline constexpr size_t schedule_step_count = static_cast<size_t>(ScheduleStep::count);

// The steps' names, as light-bench prints them and --stats keys them.
inline constexpr std::array<const char*, schedule_step_count> schedule_step_names{
    "views", "requests", "match",  "budget",  "tiles", "placements",
    "dirty", "casters",  "choose", "renders", "apply"};

// Milliseconds per step of one schedule() call.
using ScheduleStepTimes = std::array<double, schedule_step_count>;

// "views 0.45, requests 0.40, ...", for a log line.
inline std::string schedule_steps_text(const ScheduleStepTimes& ms) {
  std::string text;
  for (size_t step = 0; step < schedule_step_count; ++step) {
    char figure[48];
    std::snprintf(figure, sizeof(figure), "%s%s %.2f", step == 0 ? "" : ", ", schedule_step_names[step],
                  ms[step]);
    text += figure;
  }
  return text;
}

// Times consecutive steps into `times`: each lap() adds the time since the last lap (or since
// the clock was made) to its step.
class StepClock {
 public:
  explicit StepClock(ScheduleStepTimes& times) : times_(times) {}

  void lap(ScheduleStep step) {
    const auto now = std::chrono::steady_clock::now();
    times_[static_cast<size_t>(step)] += std::chrono::duration<double, std::milli>(now - mark_).count();
    mark_ = now;
  }

 private:
  ScheduleStepTimes& times_;
  std::chrono::steady_clock::time_point mark_ = std::chrono::steady_clock::now();
};

// lap() where a caller may time nothing.
inline void lap(StepClock* clock, ScheduleStep step) {
  if (clock != nullptr) clock->lap(step);
}

}  // namespace sg::shadows
