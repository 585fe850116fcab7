// SPDX-License-Identifier: MIT
// Where the compute raster puts each due view's depths (systems/shadows/depth_placement.h).
#include "systems/shadows/depth_placement.h"

#include <set>
#include <vector>

#include <gtest/gtest.h>

namespace sg::shadows {
namespace {

AtlasTile tile(uint32_t page, uint32_t x, uint32_t y, uint32_t size) {
  AtlasTile t;
  t.page = page;
  t.x = x;
  t.y = y;
  t.size = size;
  return t;
}

// Every view's square lies inside the buffer, no two overlap, and each sits in its region where
// its tile sits in the region's rectangle of the atlas.
void expect_consistent(const DepthPlacement& placement, const std::vector<AtlasTile>& tiles) {
  ASSERT_EQ(placement.places().size(), tiles.size());
  std::set<uint64_t> texels;
  for (size_t v = 0; v < tiles.size(); ++v) {
    const glm::uvec2 place = placement.places()[v];
    for (uint32_t y = 0; y < tiles[v].size; ++y) {
      for (uint32_t x = 0; x < tiles[v].size; ++x) {
        const uint64_t texel = place.x + uint64_t{y} * place.y + x;
        EXPECT_LT(texel, placement.texels());
        EXPECT_TRUE(texels.insert(texel).second) << "view " << v << " overlaps another";
      }
    }
  }
  uint64_t area = 0;
  for (const DepthRegion& region : placement.regions()) area += uint64_t{region.width} * region.height;
  EXPECT_EQ(area, placement.texels());
}

TEST(DepthPlacement, ABlockOfTilesCopiesAsOneRegion) {
  // A 2 x 2 block of 64-texel tiles on page 0, listed out of order.
  const std::vector<AtlasTile> tiles{tile(0, 64, 64, 64), tile(0, 0, 0, 64), tile(0, 64, 0, 64),
                                     tile(0, 0, 64, 64)};
  DepthPlacement placement;
  EXPECT_TRUE(placement.place(tiles));
  ASSERT_EQ(placement.regions().size(), 1u);
  EXPECT_EQ(placement.regions()[0].width, 128u);
  EXPECT_EQ(placement.regions()[0].height, 128u);
  EXPECT_EQ(placement.texels(), 128u * 128u);
  EXPECT_EQ(placement.places()[1], glm::uvec2(0u, 128u)) << "the block's top-left tile starts it";
  EXPECT_EQ(placement.places()[0], glm::uvec2(64u * 128u + 64u, 128u));
  expect_consistent(placement, tiles);
}

TEST(DepthPlacement, TilesOfOtherPagesOrSizesGetRegionsOfTheirOwn) {
  const std::vector<AtlasTile> tiles{tile(0, 0, 0, 64), tile(1, 0, 0, 64), tile(0, 128, 0, 32),
                                     tile(0, 256, 0, 64)};
  DepthPlacement placement;
  EXPECT_TRUE(placement.place(tiles));
  EXPECT_EQ(placement.regions().size(), 4u) << "no two of them side by side on a row of one page";
  expect_consistent(placement, tiles);
}

TEST(DepthPlacement, TheSameTilesKeepTheirPlacesUntilPlacedNowhere) {
  const std::vector<AtlasTile> tiles{tile(0, 0, 0, 64), tile(0, 64, 0, 64)};
  DepthPlacement placement;
  EXPECT_TRUE(placement.place(tiles));
  EXPECT_FALSE(placement.place(tiles)) << "the last places stand";
  placement.place_nowhere(2);
  EXPECT_EQ(placement.places()[1], glm::uvec2(0u));
  EXPECT_TRUE(placement.place(tiles)) << "placed anew after a frame placed nowhere";
  expect_consistent(placement, tiles);
}

}  // namespace
}  // namespace sg::shadows
