// SPDX-License-Identifier: MIT
// The adaptive render scale of a CPU device's window, on made-up frame times.
#include <gtest/gtest.h>

#include "sandbox/render_scale_control.h"

namespace sg::sandbox {
namespace {

constexpr size_t window = RenderScaleControl::window;

// Feeds `frames` frames of `frame_ms` each, `scene_ms` of it drawn at the render scale; the scale
// changes the control asked for, in order.
std::vector<float> feed(RenderScaleControl& control, double frame_ms, double scene_ms, size_t frames) {
  std::vector<float> changes;
  for (size_t i = 0; i < frames; ++i) {
    if (std::optional<float> scale = control.take_frame(frame_ms, scene_ms)) changes.push_back(*scale);
  }
  return changes;
}

TEST(RenderScaleControl, StartsAtTheNearestStep) {
  EXPECT_EQ(RenderScaleControl(0.5f).scale(), 0.5f);
  EXPECT_EQ(RenderScaleControl(0.55f).scale(), 0.5f);
  EXPECT_EQ(RenderScaleControl(0.65f).scale(), 0.7f);
  EXPECT_EQ(RenderScaleControl(0.9f).scale(), 1.0f);
  EXPECT_EQ(RenderScaleControl(0.1f).scale(), 0.5f) << "half size is the least it takes";
}

TEST(RenderScaleControl, StepsUpWhereTheSceneGrownByTheStepsPixelsFitsTheBudget) {
  RenderScaleControl control(0.5f, 50.0);
  // At 0.7 the scene has 1.96 times the pixels: 28 ms with a scene of 8 predicts 35.7, under
  // 0.8 x 50; the whole frame grown so (55) would not.
  EXPECT_TRUE(feed(control, 28.0, 8.0, window - 1).empty()) << "no decision before a window of frames";
  EXPECT_EQ(feed(control, 28.0, 8.0, 1), std::vector<float>{0.7f});
  EXPECT_EQ(control.judged_ms(), 28.0);
  // 36 ms with a scene of 16 at 0.7 predicts 68.7 at full size: it stays.
  EXPECT_TRUE(feed(control, 36.0, 16.0, 3 * window).empty());
  EXPECT_EQ(control.scale(), 0.7f);
  EXPECT_EQ(feed(control, 20.0, 5.0, window), std::vector<float>{1.0f});
  EXPECT_TRUE(feed(control, 1.0, 0.5, 2 * window).empty()) << "the ladder's top";
}

TEST(RenderScaleControl, StepsDownWhereFramesTakeLongerThanTheBudgetOneWindowAtATime) {
  RenderScaleControl control(1.0f, 50.0);
  EXPECT_EQ(feed(control, 130.0, 110.0, window), std::vector<float>{0.7f});
  EXPECT_EQ(control.judged_ms(), 130.0);
  // Each step is judged on a window of frames drawn after it.
  EXPECT_EQ(feed(control, 70.0, 50.0, window), std::vector<float>{0.5f});
  EXPECT_TRUE(feed(control, 130.0, 110.0, 2 * window).empty()) << "the ladder's lowest step";
}

TEST(RenderScaleControl, HoldsWithinTheBandAndJudgesTheMedian) {
  RenderScaleControl control(0.7f, 50.0);
  // 45 ms: not over 1.2 x 50, and full size would predict 45 + 25 x 1.04 = 71.
  EXPECT_TRUE(feed(control, 45.0, 25.0, 4 * window).empty());
  // A few slow frames (a map redrawn, a pipeline built) do not move the median.
  for (size_t i = 0; i < window; ++i) {
    EXPECT_FALSE(control.take_frame(i % 6 == 5 ? 400.0 : 45.0, 25.0));
  }
  EXPECT_EQ(control.scale(), 0.7f);
}

}  // namespace
}  // namespace sg::sandbox
