// SPDX-License-Identifier: MIT
// The run's GPU time log: a completed frame's timings counted once however often they are
// offered (a window offers the latest every frame), and a pass missing from a frame counted 0.
#include <memory>
#include <optional>

#include <gtest/gtest.h>

#include "systems/frame/gpu_time_log.h"

namespace sg::test {
namespace {

vk::FrameTimings timed_frame(uint64_t number, std::vector<std::string> names, std::vector<double> ms) {
  auto plan = std::make_shared<rg::CompiledPlan>();
  for (std::string& name : names) plan->passes.push_back({.name = std::move(name)});
  return {number, plan, std::move(ms)};
}

TEST(GpuTimeLog, EachFrameCountsOnce) {
  GpuTimeLog log;
  EXPECT_FALSE(log.add(std::nullopt)) << "no timings yet";
  const vk::FrameTimings first = timed_frame(7, {"shadows", "lighting"}, {1.0, 2.0});
  EXPECT_TRUE(log.add(first));
  EXPECT_FALSE(log.add(first)) << "the same frame offered again";
  EXPECT_TRUE(log.add(timed_frame(8, {"lighting"}, {4.0})));
  ASSERT_EQ(log.frame_ms().size(), 2u);
  EXPECT_EQ(log.frame_ms()[0], 3.0);
  EXPECT_EQ(log.frame_ms()[1], 4.0);
  EXPECT_EQ(log.frame_numbers(), (std::vector<uint64_t>{7, 8}));
  const std::vector<PassTime> passes = log.pass_summaries();
  ASSERT_EQ(passes.size(), 2u);
  EXPECT_EQ(passes[0].name, "shadows");
  EXPECT_EQ(passes[0].gpu_ms.min, 0.0) << "absent from the second frame";
  EXPECT_EQ(passes[1].gpu_ms.max, 4.0);
}

}  // namespace
}  // namespace sg::test
