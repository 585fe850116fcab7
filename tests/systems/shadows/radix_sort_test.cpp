// SPDX-License-Identifier: MIT
// The shadow code's radix sort: the order std::stable_sort gives, for whole and partial keys.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "systems/shadows/radix_sort.h"

namespace sg::shadows {
namespace {

struct Item {
  uint64_t key;
  uint32_t payload;
  friend bool operator==(const Item&, const Item&) = default;
};

std::vector<Item> random_items(size_t count, uint64_t key_mask) {
  std::mt19937_64 random(5);
  std::vector<Item> items;
  for (uint32_t i = 0; i < count; ++i) items.push_back({random() & key_mask, i});
  return items;
}

TEST(RadixSort, SortsLikeAStableSortOnWholeKeys) {
  std::vector<Item> items = random_items(5000, ~uint64_t{0});
  std::vector<Item> expected = items;
  std::stable_sort(expected.begin(), expected.end(),
                   [](const Item& a, const Item& b) { return a.key < b.key; });
  std::vector<Item> scratch;
  radix_sort(items, scratch, [](const Item& item) { return item.key; });
  EXPECT_EQ(items, expected);
}

// Few distinct keys in a few bits, most bytes equal everywhere (skipped), and a key width that
// is not a whole number of bytes: bits above it must not count.
TEST(RadixSort, KeepsTheOrderOfEqualKeysAndIgnoresBitsAboveTheKey) {
  std::vector<Item> items = random_items(3000, 0xF0000000000001FFull);
  const auto low_bits = [](const Item& item) { return item.key & 0x1FF; };
  std::vector<Item> expected = items;
  std::stable_sort(expected.begin(), expected.end(),
                   [&](const Item& a, const Item& b) { return low_bits(a) < low_bits(b); });
  std::vector<Item> scratch;
  radix_sort(
      items, scratch, [](const Item& item) { return item.key; }, 9);
  EXPECT_EQ(items, expected);
}

}  // namespace
}  // namespace sg::shadows
