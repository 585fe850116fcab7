// The shadow storage's sizing policy (ShadowMapArrays creates what it asks for).
#include <gtest/gtest.h>

#include "systems/shadows/shadow_storage_size.h"

namespace sg::shadows {
namespace {

constexpr uint32_t min_resolution = 16;

TEST(ShadowStorageSize, StartsWithOneLayerAndOneCubeOfTheSmallestSize) {
  const ShadowStorageSize size = fit_shadow_storage({}, {}, min_resolution);
  EXPECT_EQ(size.maps, (ShadowArraySize{min_resolution, 1}));
  EXPECT_EQ(size.cubes, (ShadowArraySize{min_resolution, 1}));
}

TEST(ShadowStorageSize, GrowsByHalfAgainSoLightsAddedOneByOneRarelyRecreateIt) {
  const ShadowStorageSize current{{1024, 10}, {512, 4}};
  const ShadowStorageSize one_more = fit_shadow_storage(current, {{1024, 11}, {512, 5}}, min_resolution);
  EXPECT_EQ(one_more.maps.count, 15u);
  EXPECT_EQ(one_more.cubes.count, 6u);

  // Adding lights one at a time from 1 to 1,000 recreates the layers a logarithmic number of times.
  ShadowStorageSize size{};
  int recreations = 0;
  for (uint32_t lights = 1; lights <= 1000; ++lights) {
    const ShadowStorageSize next = fit_shadow_storage(size, {{64, lights}, {64, 0}}, min_resolution);
    recreations += next.maps != size.maps;
    size = next;
    ASSERT_GE(size.maps.count, lights);
  }
  EXPECT_LE(recreations, 20);
}

TEST(ShadowStorageSize, AJumpBeyondHalfAgainGetsExactlyWhatIsNeeded) {
  const ShadowStorageSize size =
      fit_shadow_storage({{256, 4}, {256, 4}}, {{256, 100}, {256, 4}}, min_resolution);
  EXPECT_EQ(size.maps.count, 100u);
  EXPECT_EQ(size.cubes.count, 4u);
}

TEST(ShadowStorageSize, NeverShrinksWhileRunning) {
  const ShadowStorageSize current{{2048, 40}, {1024, 8}};
  EXPECT_EQ(fit_shadow_storage(current, {{512, 3}, {64, 0}}, min_resolution), current);
}

TEST(ShadowStorageSize, ResolutionFollowsTheLargestRequest) {
  const ShadowStorageSize size =
      fit_shadow_storage({{512, 2}, {256, 2}}, {{1024, 2}, {8, 2}}, min_resolution);
  EXPECT_EQ(size.maps.resolution, 1024u);
  EXPECT_EQ(size.cubes.resolution, 256u);
}

}  // namespace
}  // namespace sg::shadows
