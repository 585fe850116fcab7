// SPDX-License-Identifier: MIT
// The whole-frame error on hand-made (pixel, light) pairs, without a GPU.
#include <gtest/gtest.h>

#include "tools/reference/frame_error.h"

namespace sg::reference {
namespace {

// Light `light` over every pixel of a 20 x 10 frame with weight `weight`: the left half shadowed
// in the hard reference, the engine agreeing everywhere.
std::vector<TracedPair> half_shadowed(uint32_t light, float weight) {
  std::vector<TracedPair> pairs;
  for (uint32_t y = 0; y < 10; ++y) {
    for (uint32_t x = 0; x < 20; ++x) {
      const float visible = x < 10 ? 0.0f : 1.0f;
      pairs.push_back({y * 20 + x, light, 1.0f - visible, weight, visible, visible});
    }
  }
  return pairs;
}

TEST(FrameError, AnEngineEqualToTheReferenceHasNoError) {
  const FrameError e = frame_error(half_shadowed(0, 1.0f), 20, 10, 2);
  EXPECT_EQ(e.lit_pixels, 200u - 4 * 10) << "two columns each side of the edge are in the band";
  EXPECT_EQ(e.band_pairs, 40u);
  EXPECT_EQ(e.misclassified, 0.0);
  EXPECT_EQ(e.mae, 0.0);
  ASSERT_EQ(e.lights.size(), 1u);
  EXPECT_DOUBLE_EQ(e.lights[0].weight_share, 1.0);
}

TEST(FrameError, APixelsLightsCountByTheirWeightThere) {
  // Light 0 (weight 1) wrong at one pixel deep in its shadow; light 1 (weight 3) right there.
  std::vector<TracedPair> pairs = half_shadowed(0, 1.0f);
  pairs[5 * 20 + 2].shade = 0.0f;
  const std::vector<TracedPair> other = half_shadowed(1, 3.0f);
  pairs.insert(pairs.end(), other.begin(), other.end());
  const FrameError e = frame_error(pairs, 20, 10, 2);
  EXPECT_EQ(e.lit_pixels, 160u);
  EXPECT_DOUBLE_EQ(e.misclassified, 0.25 / 160.0);
  EXPECT_DOUBLE_EQ(e.mae, 0.25 / 160.0);
  ASSERT_EQ(e.lights.size(), 2u);
  EXPECT_EQ(e.lights[0].light, 0u) << "the light that adds the error comes first";
  EXPECT_DOUBLE_EQ(e.lights[0].frame_misclassified, e.misclassified);
  EXPECT_DOUBLE_EQ(e.lights[0].weight_share, 0.25);
  EXPECT_DOUBLE_EQ(e.lights[1].frame_misclassified, 0.0);
}

TEST(FrameError, OnlyALightsOwnEdgeMakesItsBand) {
  // Light 1 shadows nothing, and is wrong at a pixel in light 0's band: that pair counts.
  std::vector<TracedPair> pairs = half_shadowed(0, 1.0f);
  for (uint32_t pixel = 0; pixel < 200; ++pixel) {
    pairs.push_back({pixel, 1, pixel == 5 * 20 + 10 ? 1.0f : 0.0f, 1.0f, 1.0f, 1.0f});
  }
  const FrameError e = frame_error(pairs, 20, 10, 2);
  EXPECT_EQ(e.band_pairs, 40u);
  EXPECT_EQ(e.lit_pixels, 200u);
  EXPECT_DOUBLE_EQ(e.misclassified, 1.0 / 200.0);
}

TEST(FrameError, PairsWithoutWeightAreLeftOut) {
  std::vector<TracedPair> pairs = half_shadowed(0, 1.0f);
  pairs.push_back({0, 1, 1.0f, 0.0f, 1.0f, 1.0f});  // wrong, but its light adds nothing there
  const FrameError e = frame_error(pairs, 20, 10, 2);
  EXPECT_EQ(e.misclassified, 0.0);
  EXPECT_EQ(e.lights.size(), 1u);
}

}  // namespace
}  // namespace sg::reference
