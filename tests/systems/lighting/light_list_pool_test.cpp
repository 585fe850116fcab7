// SPDX-License-Identifier: MIT
// How the light lists' pool is sized from what frames asked for (LightListPool), on the CPU.
#include "systems/lighting/light_list_pool.h"

#include <gtest/gtest.h>

namespace sg::test {
namespace {

constexpr uint32_t tiles = 8160;  // 1920x1080 in 16-pixel tiles
constexpr uint64_t unlimited = uint64_t{1} << 30;

TEST(LightListPool, HoldsEveryLightInEveryTileUpToTheSureSize) {
  const LightListPool pool(unlimited);
  EXPECT_EQ(pool.entries(tiles, 10), 131072u) << "8,160 x 10 rounded up to a power of two";
  EXPECT_EQ(pool.entries(tiles, 1024), LightListPool::sure_entries);
  EXPECT_EQ(pool.entries(tiles, 16384), LightListPool::sure_entries) << "before any frame asked for more";
  EXPECT_EQ(pool.entries(tiles, 0), 1u) << "a buffer is never empty";
}

TEST(LightListPool, GrowsAtOnceToTwiceWhatAFrameAsked) {
  LightListPool pool(unlimited);
  pool.asked(6'000'000);
  EXPECT_EQ(pool.entries(tiles, 16384), 16u << 20) << "the power of two at or past 12,000,000";
  pool.asked(8'300'000);
  EXPECT_EQ(pool.entries(tiles, 16384), 16u << 20) << "still more than twice";
  pool.asked(8'400'000);
  EXPECT_EQ(pool.entries(tiles, 16384), 32u << 20);
  EXPECT_EQ(pool.entries(tiles, 10), 131072u) << "still no more than every light in every tile";
}

TEST(LightListPool, NeverPastTheDevicesLimit) {
  LightListPool pool(5'000'000);
  EXPECT_EQ(pool.entries(tiles, 4096), 5'000'000u);
  pool.asked(40'000'000);
  EXPECT_EQ(pool.entries(tiles, 16384), 5'000'000u);
}

TEST(LightListPool, ShrinksOnlyAfterManyFramesAskedForAnEighth) {
  LightListPool pool(unlimited);
  pool.asked(16'000'000);
  const uint64_t grown = pool.entries(tiles, 16384);
  ASSERT_EQ(grown, 32u << 20);
  for (uint64_t frame = 1; frame < LightListPool::shrink_after; ++frame) {
    pool.asked(3'000'000);
    ASSERT_EQ(pool.entries(tiles, 16384), grown) << "frame " << frame;
  }
  pool.asked(5'000'000);  // more than an eighth: counting starts again
  for (uint64_t frame = 1; frame < LightListPool::shrink_after; ++frame) pool.asked(3'000'000);
  EXPECT_EQ(pool.entries(tiles, 16384), grown);
  pool.asked(3'000'000);
  EXPECT_EQ(pool.entries(tiles, 16384), LightListPool::sure_entries) << "6,000,000 rounds to 2^23";
}

TEST(LightListPool, AskingAroundOneSizeKeepsIt) {
  LightListPool pool(unlimited);
  pool.asked(6'000'000);
  const uint64_t sized = pool.entries(tiles, 16384);
  ASSERT_EQ(sized, 16u << 20);
  for (int frame = 0; frame < 1000; ++frame) {
    pool.asked(frame % 2 ? 5'000'000 : 8'000'000);
    ASSERT_EQ(pool.entries(tiles, 16384), sized) << "frame " << frame;
  }
}

}  // namespace
}  // namespace sg::test
