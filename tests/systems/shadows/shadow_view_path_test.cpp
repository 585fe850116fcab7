// SPDX-License-Identifier: MIT
// automatic's per-frame choice of shadow raster on GPUs.
#include <gtest/gtest.h>

#include "systems/shadows/shadow_view_path.h"

namespace sg::shadows {
namespace {

// The H200 cases the model was fitted to (shadow work, compute against hardware).
TEST(RasterForViews, FollowsTheMeasuredFasterRaster) {
  EXPECT_EQ(raster_for_views(1, 2048u * 2048u), ShadowRaster::hardware);    // 7.20 against 0.34 ms
  EXPECT_EQ(raster_for_views(57, 1024u * 1024u), ShadowRaster::hardware);   // 4.31 against 1.52 ms
  EXPECT_EQ(raster_for_views(897, 1024u * 1024u), ShadowRaster::compute);   // 4.93 against 11.77 ms
  EXPECT_EQ(raster_for_views(3585, 1024u * 1024u), ShadowRaster::compute);  // 7.60 against 45 ms
  // Small views only: the hardware's setup per view costs more than compute's.
  EXPECT_EQ(raster_for_views(60, 0), ShadowRaster::compute);
}

}  // namespace
}  // namespace sg::shadows
