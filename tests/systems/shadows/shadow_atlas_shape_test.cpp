// SPDX-License-Identifier: MIT
// The shadow atlas's shape: page size and count from the budget within the device's limits.
#include <gtest/gtest.h>

#include "systems/shadows/shadow_atlas_shape.h"

namespace sg::shadows {
namespace {

constexpr uint64_t mib = 1ull << 20;
constexpr uint64_t page_4096_bytes = 4096ull * 4096 * 4;  // 64 MiB

TEST(ShadowAtlasShape, BudgetBuysWholePagesOf4096) {
  const DeviceShadowLimits device{16384, 2048, 4ull << 30, 80ull << 30};
  const AtlasShape shape = atlas_shape(1024 * mib, device);
  EXPECT_EQ(shape.page_size, 4096u);
  EXPECT_EQ(shape.max_pages, 16u);
  EXPECT_EQ(shape.budget_bytes, 16 * page_4096_bytes);
  EXPECT_EQ(atlas_shape(1000 * mib, device).max_pages, 15u);  // rounded down: never over budget
}

TEST(ShadowAtlasShape, DeviceLimitsCapThePages) {
  // lavapipe: one allocation of at most 2 GiB, so at most 32 pages of 64 MiB in one image.
  const DeviceShadowLimits lavapipe{16384, 2048, 2ull << 30, 24ull << 30};
  EXPECT_EQ(atlas_shape(8192 * mib, lavapipe).max_pages, 32u);
  const DeviceShadowLimits few_layers{4096, 8, 64ull << 30, 64ull << 30};
  EXPECT_EQ(atlas_shape(8192 * mib, few_layers).max_pages, 8u);
}

// Static layers cost a page's bytes again, and live in one storage buffer.
TEST(ShadowAtlasShape, StaticLayersPayForEachPageTwice) {
  DeviceShadowLimits device{16384, 2048, 4ull << 30, 80ull << 30};
  device.max_storage_buffer_bytes = 4ull << 30;
  const AtlasShape shape = atlas_shape(1024 * mib, device, true);
  EXPECT_EQ(shape.page_size, 4096u);
  EXPECT_EQ(shape.max_pages, 8u);
  EXPECT_EQ(shape.budget_bytes, 16 * page_4096_bytes);
  device.max_storage_buffer_bytes = 3 * page_4096_bytes;
  EXPECT_EQ(atlas_shape(1024 * mib, device, true).max_pages, 3u);
  EXPECT_EQ(atlas_shape(1024 * mib, device).max_pages, 16u) << "no buffer, no buffer limit";
  EXPECT_EQ(atlas_shape(100 * mib, device, true).page_size, 2048u) << "two 64 MiB copies do not fit";
}

TEST(ShadowAtlasShape, SmallBudgetsGetSmallerPagesAndAtLeastOne) {
  const DeviceShadowLimits device{};
  const AtlasShape shape = atlas_shape(16 * mib, device);
  EXPECT_EQ(shape.page_size, 2048u);  // 16 MiB
  EXPECT_EQ(shape.max_pages, 1u);
  const AtlasShape tiny = atlas_shape(1, device);
  EXPECT_EQ(tiny.page_size, smallest_atlas_page);
  EXPECT_EQ(tiny.max_pages, 1u);
}

TEST(ShadowAtlasShape, DefaultBudgetFollowsTheHeapWithinBounds) {
  EXPECT_EQ(default_shadow_budget({4096, 256, 1ull << 30, 8ull << 30}), 1024 * mib);
  EXPECT_EQ(default_shadow_budget({4096, 256, 1ull << 30, 140ull << 30}), 2048 * mib);
  EXPECT_EQ(default_shadow_budget({4096, 256, 1ull << 30, 256 * mib}), 64 * mib);
}

TEST(ShadowAtlasShape, PagesGrowByHalfAgainAndNeverShrink) {
  EXPECT_EQ(atlas_pages_to_create(0, 0, 16), 1u);
  EXPECT_EQ(atlas_pages_to_create(4, 2, 16), 4u);
  EXPECT_EQ(atlas_pages_to_create(4, 5, 16), 6u);
  EXPECT_EQ(atlas_pages_to_create(4, 9, 16), 9u);
  EXPECT_EQ(atlas_pages_to_create(12, 13, 16), 16u);
  int recreations = 0;
  uint32_t pages = 1;
  for (uint32_t needed = 1; needed <= 1000; ++needed) {
    const uint32_t next = atlas_pages_to_create(pages, needed, 2048);
    recreations += next != pages;
    pages = next;
    ASSERT_GE(pages, needed);
  }
  EXPECT_LE(recreations, 20);
}

}  // namespace
}  // namespace sg::shadows
