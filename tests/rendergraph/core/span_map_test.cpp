// SPDX-License-Identifier: MIT
#include "rendergraph/core/span_map.h"

#include <gtest/gtest.h>

namespace sg::rg {
namespace {

TEST(SpanMap, SplitsAtTheEdgesOfAnUpdateAndVisitsOnlyInside) {
  SpanMap<std::uint32_t, int> map(10, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> visited;
  map.update(3, 4, [&](std::uint32_t first, std::uint32_t count, int& value) {
    visited.emplace_back(first, count);
    value = 7;
  });
  EXPECT_EQ(visited, (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{3, 4}}));
  ASSERT_EQ(map.spans().size(), 3u);
  EXPECT_EQ(map.spans()[0].count, 3u);
  EXPECT_EQ(map.spans()[1].value, 7);
  EXPECT_EQ(map.spans()[2].first, 7u);
}

TEST(SpanMap, JoinsNeighboursThatBecomeEqual) {
  SpanMap<std::uint32_t, int> map(6, 0);
  for (std::uint32_t i = 0; i < 6; ++i) {
    map.update(i, 1, [](std::uint32_t, std::uint32_t, int& value) { value = 1; });
  }
  ASSERT_EQ(map.spans().size(), 1u);
  EXPECT_EQ(map.spans()[0].count, 6u);
  EXPECT_EQ(map.spans()[0].value, 1);
}

TEST(SubresourceMap, VisitsOneSpanPerMipInsideTheRange) {
  SubresourceMap<int> map(3, 8, 0);
  std::vector<SubresourceRange> visited;
  map.update({1, 2, 2, 3}, [&](const SubresourceRange& range, int& value) {
    visited.push_back(range);
    value = 5;
  });
  EXPECT_EQ(visited, (std::vector<SubresourceRange>{{1, 1, 2, 3}, {2, 1, 2, 3}}));
}

TEST(MergeIntoRanges, JoinsLayersThenMips) {
  const std::vector<RangeValue<int>> pieces{
      {{0, 1, 0, 2}, 1}, {{0, 1, 2, 2}, 1}, {{0, 1, 4, 1}, 2}, {{1, 1, 0, 4}, 1}, {{2, 1, 0, 4}, 1}};
  const auto ranges = merge_into_ranges(pieces);
  ASSERT_EQ(ranges.size(), 2u);
  EXPECT_EQ(ranges[0].range, (SubresourceRange{0, 3, 0, 4}));
  EXPECT_EQ(ranges[1].range, (SubresourceRange{0, 1, 4, 1}));
  EXPECT_EQ(ranges[1].value, 2);
}

}  // namespace
}  // namespace sg::rg
