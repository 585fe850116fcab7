// SPDX-License-Identifier: MIT
// The window's frame-rate cap, on a made-up clock.
#include <gtest/gtest.h>

#include "sandbox/frame_pacer.h"

namespace sg::sandbox {
namespace {

using namespace std::chrono_literals;

TEST(FramePacer, FramesStartAPeriodApartAndALateOneIsNotMadeUpFor) {
  FramePacer pacer;
  const FramePacer::Clock::time_point t0{};
  EXPECT_EQ(pacer.wait(t0), 0ns) << "no cap";
  EXPECT_EQ(pacer.wait(t0 + 1ms), 0ns);
  pacer.set_max_fps(50.0);  // 20 ms
  EXPECT_EQ(pacer.wait(t0), 0ns) << "the first frame starts at once";
  EXPECT_EQ(pacer.wait(t0 + 5ms), 15ms);
  EXPECT_EQ(pacer.wait(t0 + 20ms), 20ms) << "started at 20 ms, the next at 40";
  EXPECT_EQ(pacer.wait(t0 + 100ms), 0ns) << "late: at once";
  EXPECT_EQ(pacer.wait(t0 + 101ms), 19ms) << "a period after the late frame, no burst";
  pacer.set_max_fps(0.0);
  EXPECT_EQ(pacer.wait(t0 + 121ms), 0ns);
  pacer.set_max_fps(-3.0);
  EXPECT_EQ(pacer.max_fps(), 0.0);
}

}  // namespace
}  // namespace sg::sandbox
