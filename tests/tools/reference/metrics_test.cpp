// SPDX-License-Identifier: MIT
// The accuracy metrics on small hand-made images, without a GPU.
#include <cmath>

#include <gtest/gtest.h>

#include "tools/reference/metrics.h"

namespace sg::reference {
namespace {

// 20 x 10 pixels, all measured: the left half shadowed in the hard reference, a one-pixel-wide
// penumbra (0.5) in the soft one at the edge, the engine equal to the soft reference.
ShadowImages half_shadowed() {
  ShadowImages images{20, 10, std::vector<bool>(200, true), {}, {}, {}};
  for (uint32_t y = 0; y < 10; ++y) {
    for (uint32_t x = 0; x < 20; ++x) {
      images.hard.push_back(x < 10 ? 0.0f : 1.0f);
      images.soft.push_back(x < 9 ? 0.0f : x == 9 || x == 10 ? 0.5f : 1.0f);
    }
  }
  images.engine = images.soft;
  return images;
}

TEST(ShadowMetrics, AnEngineEqualToTheReferenceHasNoError) {
  const ShadowMetrics m = shadow_metrics(half_shadowed(), 2);
  EXPECT_EQ(m.measured, 200u);
  EXPECT_EQ(m.shadowed, 100u);
  EXPECT_EQ(m.outside_band, 200u - 4 * 10) << "two columns each side of the edge are in the band";
  EXPECT_EQ(m.misclassified, 0.0);
  EXPECT_EQ(m.acne, 0.0);
  EXPECT_EQ(m.penumbra.pixels, 20u);
  EXPECT_EQ(m.penumbra.mean_absolute, 0.0);
  EXPECT_EQ(m.umbra_and_lit.rms, 0.0);
}

TEST(ShadowMetrics, WrongPixelsCountOnlyOutsideTheEdgeBand) {
  ShadowImages images = half_shadowed();
  images.engine[5 * 20 + 2] = 1.0f;   // deep in the shadow: misclassified
  images.engine[5 * 20 + 11] = 0.0f;  // next to the edge: in the band, not counted
  const ShadowMetrics m = shadow_metrics(images, 2);
  EXPECT_DOUBLE_EQ(m.misclassified, 1.0 / 160.0);
}

TEST(ShadowMetrics, DarkenedLitPixelsAreAcne) {
  ShadowImages images = half_shadowed();
  for (uint32_t y = 0; y < 10; ++y) images.engine[y * 20 + 18] = 0.7f;  // a dark stripe on lit ground
  const ShadowMetrics m = shadow_metrics(images, 2);
  EXPECT_EQ(m.lit, 80u);
  EXPECT_DOUBLE_EQ(m.acne, 10.0 / 80.0) << "10 of the 80 lit pixels outside the band";
  EXPECT_NEAR(m.umbra_and_lit.mean_absolute, 10 * 0.3 / 180.0, 1e-6);
  EXPECT_NEAR(m.umbra_and_lit.rms, std::sqrt(10 * 0.09 / 180.0), 1e-6);
  EXPECT_EQ(m.misclassified, 0.0) << "0.7 is still on the lit side of 0.5";
}

TEST(ShadowMetrics, PenumbraErrorIsMeasuredAgainstTheSoftReference) {
  ShadowImages images = half_shadowed();
  images.engine = images.hard;  // a hard edge where the soft reference is half lit
  const ShadowMetrics m = shadow_metrics(images, 2);
  EXPECT_DOUBLE_EQ(m.penumbra.mean_absolute, 0.5);
  EXPECT_DOUBLE_EQ(m.penumbra.rms, 0.5);
  EXPECT_EQ(m.umbra_and_lit.mean_absolute, 0.0);
}

TEST(ShadowMetrics, UnmeasuredPixelsAreIgnored) {
  ShadowImages images = half_shadowed();
  images.engine[5 * 20 + 2] = 1.0f;
  images.measured[5 * 20 + 2] = false;
  const ShadowMetrics m = shadow_metrics(images, 2);
  EXPECT_EQ(m.measured, 199u);
  EXPECT_EQ(m.misclassified, 0.0);
}

}  // namespace
}  // namespace sg::reference
