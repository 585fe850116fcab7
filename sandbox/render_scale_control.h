// SPDX-License-Identifier: MIT
#pragma once
// The render scale of a CPU device's window, adapted to the GPU frame time when neither
// --render-scale nor the Frame panel chose one: it starts at half size, the least it takes, steps
// up where the step above would still fit the budget and back down where the frames take longer
// than it. On lavapipe (2-core VM, 1280x720, 2026-12-05) `default` takes 45 ms a frame at half
// scale and 125-135 at full, `point-room` 28 at full: one fixed scale is either blurred or slow.
//
// Each decision waits for a window of frames drawn at the current scale, so a change is judged on
// the frames after it. A step up is predicted from the frame's scene passes (those drawn at the
// render scale) grown by the step's pixels, the rest of the frame (panels, the upscale, the
// present) as it is; the scene's shadow maps do not grow with it, so the prediction is high and
// the step down does not follow at once.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace sg::sandbox {

class RenderScaleControl {
 public:
  static constexpr std::array<float, 3> ladder{0.5f, 0.7f, 1.0f};
  static constexpr size_t window = 24;               // frames a decision looks at
  static constexpr double default_budget_ms = 50.0;  // 20 frames a second

  // Starts at the ladder's step nearest `scale`.
  explicit RenderScaleControl(float scale, double budget_ms = default_budget_ms) : budget_ms_(budget_ms) {
    const auto nearest = std::min_element(ladder.begin(), ladder.end(), [scale](float a, float b) {
      return std::abs(a - scale) < std::abs(b - scale);
    });
    step_ = size_t(nearest - ladder.begin());
  }

  float scale() const { return ladder[step_]; }
  double budget_ms() const { return budget_ms_; }
  // The median GPU frame time the last decision was made on (0 before the first).
  double judged_ms() const { return judged_ms_; }

  // Takes a frame drawn at scale() that took `frame_ms` on the GPU, `scene_ms` of it in the passes
  // drawn at the render scale; returns the scale to draw at from now on where it should change.
  std::optional<float> take_frame(double frame_ms, double scene_ms) {
    frames_.push_back(frame_ms);
    scenes_.push_back(scene_ms);
    if (frames_.size() < window) return std::nullopt;
    judged_ms_ = median(frames_);
    const double scene = median(scenes_);
    frames_.clear();
    scenes_.clear();
    if (judged_ms_ > 1.2 * budget_ms_ && step_ > 0) {
      --step_;
      return scale();
    }
    if (step_ + 1 < ladder.size()) {
      const double area = double(ladder[step_ + 1]) / double(ladder[step_]);
      if (judged_ms_ + scene * (area * area - 1.0) < 0.8 * budget_ms_) {
        ++step_;
        return scale();
      }
    }
    return std::nullopt;
  }

 private:
  static double median(std::vector<double>& samples) {
    std::nth_element(samples.begin(), samples.begin() + samples.size() / 2, samples.end());
    return samples[samples.size() / 2];
  }

  double budget_ms_;
  size_t step_ = 0;
  double judged_ms_ = 0.0;
  std::vector<double> frames_;  // at the current scale, since the last decision
  std::vector<double> scenes_;
};

}  // namespace sg::sandbox
