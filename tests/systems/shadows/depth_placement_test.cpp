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

// Every view's square lies inside the buffer, no two overlap, and together they fill it.
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
  EXPECT_EQ(texels.size(), placement.texels()) << "texels no view writes";
}

TEST(DepthPlacement, ABlockOfTilesCopiesAsOneRegion) {
  // A 2 x 2 block of 64-texel tiles on page 0, listed out of order.
  const std::vector<AtlasTile> tiles{tile(0, 64, 64, 64), tile(0, 0, 0, 64), tile(0, 64, 0, 64),
                                     tile(0, 0, 64, 64)};
  DepthPlacement placement;
  EXPECT_TRUE(placement.place(tiles, 0));
  ASSERT_EQ(placement.copied().size(), 1u);
  EXPECT_EQ(placement.copied()[0].width, 128u);
  EXPECT_EQ(placement.copied()[0].height, 128u);
  EXPECT_EQ(placement.texels(), 128u * 128u);
  EXPECT_EQ(placement.places()[1], glm::uvec2(0u, 128u)) << "the block's top-left tile starts it";
  EXPECT_EQ(placement.places()[0], glm::uvec2(64u * 128u + 64u, 128u));
  expect_consistent(placement, tiles);
}

TEST(DepthPlacement, TilesOfOtherPagesOrSizesGetRegionsOfTheirOwn) {
  const std::vector<AtlasTile> tiles{tile(0, 0, 0, 64), tile(1, 0, 0, 64), tile(0, 128, 0, 32),
                                     tile(0, 256, 0, 64)};
  DepthPlacement placement;
  EXPECT_TRUE(placement.place(tiles, 0));
  EXPECT_EQ(placement.copied().size(), 4u) << "no two of them side by side on a row of one page";
  expect_consistent(placement, tiles);
}

TEST(DepthPlacement, RectanglesBelowTheCopiedSizeAreDrawnViewByView) {
  // Views 0 and 2 form a 2 x 1 block of 64-texel tiles (8,192 texels); views 1, 3 and 4 lie
  // apart; view 3's 128-texel tile alone reaches the copied size.
  const std::vector<AtlasTile> tiles{tile(0, 0, 0, 64), tile(0, 512, 0, 32), tile(0, 64, 0, 64),
                                     tile(1, 0, 0, 128), tile(1, 512, 512, 16)};
  DepthPlacement placement;
  EXPECT_TRUE(placement.place(tiles, 128 * 128));
  ASSERT_EQ(placement.copied().size(), 1u);
  EXPECT_EQ(placement.copied()[0].corner.page, 1u);
  EXPECT_EQ(placement.copied()[0].width, 128u);
  const std::vector<ViewRun> drawn(placement.drawn().begin(), placement.drawn().end());
  ASSERT_EQ(drawn.size(), 2u) << "views 0-2, then view 4";
  EXPECT_EQ(drawn[0].first, 0u);
  EXPECT_EQ(drawn[0].count, 3u);
  EXPECT_EQ(drawn[1].first, 4u);
  EXPECT_EQ(drawn[1].count, 1u);
  EXPECT_EQ(placement.places()[2].y, 128u) << "the block's views share its rows";
  EXPECT_TRUE(placement.place(tiles, 8192)) << "another size places anew";
  EXPECT_EQ(placement.copied().size(), 2u) << "the block is copied too";
  expect_consistent(placement, tiles);
}

TEST(DepthPlacement, TheSameTilesKeepTheirPlacesUntilPlacedNowhere) {
  const std::vector<AtlasTile> tiles{tile(0, 0, 0, 64), tile(0, 64, 0, 64)};
  DepthPlacement placement;
  EXPECT_TRUE(placement.place(tiles, 0));
  EXPECT_FALSE(placement.place(tiles, 0)) << "the last places stand";
  placement.place_nowhere(2);
  EXPECT_EQ(placement.places()[1], glm::uvec2(0u));
  EXPECT_TRUE(placement.place(tiles, 0)) << "placed anew after a frame placed nowhere";
  expect_consistent(placement, tiles);
}

}  // namespace
}  // namespace sg::shadows
