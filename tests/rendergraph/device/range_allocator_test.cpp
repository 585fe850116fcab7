// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "rendergraph/device/range_allocator.h"

namespace sg::vk {
namespace {

TEST(RangeAllocator, AlignsAndPacksFirstFit) {
  RangeAllocator a(1024);
  EXPECT_EQ(a.allocate(100, 1), 0u);
  EXPECT_EQ(a.allocate(10, 256), 256u);  // padding 100..256 stays free
  EXPECT_EQ(a.allocate(50, 4), 100u);    // first fit reuses the padding
  EXPECT_EQ(a.used(), 160u);
}

TEST(RangeAllocator, RefusesWhatDoesNotFit) {
  RangeAllocator a(256);
  EXPECT_EQ(a.allocate(200, 1), 0u);
  EXPECT_FALSE(a.allocate(100, 1).has_value());
  EXPECT_FALSE(a.allocate(0, 1).has_value());
}

TEST(RangeAllocator, FreeCoalescesNeighbours) {
  RangeAllocator a(300);
  const uint64_t x = *a.allocate(100, 1);
  const uint64_t y = *a.allocate(100, 1);
  const uint64_t z = *a.allocate(100, 1);
  a.free(x, 100);
  a.free(z, 100);
  EXPECT_EQ(a.free_range_count(), 2u);
  EXPECT_FALSE(a.allocate(200, 1).has_value());
  a.free(y, 100);
  EXPECT_EQ(a.free_range_count(), 1u);
  EXPECT_TRUE(a.empty());
  EXPECT_EQ(a.allocate(300, 1), 0u);
}

}  // namespace
}  // namespace sg::vk
