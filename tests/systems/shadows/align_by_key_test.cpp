// SPDX-License-Identifier: MIT
// Per-light state matched to a frame's lights by key: KeyPlaces' table and align_by_key.
#include <algorithm>
#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

#include <gtest/gtest.h>

#include "systems/shadows/align_by_key.h"
#include "systems/shadows/frame_lights.h"

namespace sg::shadows {
namespace {

struct Item {
  uint64_t key;
};

struct Entry {
  uint64_t key = 0;
  uint32_t value = 0;  // what a frame's state carries over
};

TEST(KeyPlaces, FindsEveryKeyItWasGivenAndNoOther) {
  // Entity keys (generation above bit 32), and cascade keys, whose top bits alone differ.
  std::vector<uint64_t> keys;
  for (uint32_t index = 0; index < 5000; ++index) keys.push_back(uint64_t{index % 3} << 32 | index);
  const ecs::Entity sun{7, 2};
  for (uint32_t k = 0; k < 4; ++k) keys.push_back(cascade_key(sun, k));
  KeyPlaces places;
  places.assign(keys.size(), [&](size_t k) { return keys[k]; });
  for (size_t k = 0; k < keys.size(); ++k) EXPECT_EQ(places.find(keys[k]), k) << keys[k];
  EXPECT_EQ(places.find(light_key(sun)), KeyPlaces::none);  // its cascades only
  EXPECT_EQ(places.find(uint64_t{5} << 32 | 1), KeyPlaces::none);
  EXPECT_EQ(places.find(0xFFFFFFFFFFFFull), KeyPlaces::none);

  places.assign(0, [](size_t) { return uint64_t{0}; });
  EXPECT_EQ(places.find(keys[0]), KeyPlaces::none);
}

TEST(AlignByKey, CarriesEachKeysEntryOverDropsTheGoneAndStartsTheNew) {
  std::mt19937 random(3);
  std::vector<Entry> entries;
  for (uint32_t k = 0; k < 3000; ++k) entries.push_back({uint64_t{k} * 7 + 1, k + 100});
  std::unordered_map<uint64_t, uint32_t> value_of;
  for (const Entry& entry : entries) value_of[entry.key] = entry.value;

  // The next frame: a third of the keys gone, new ones among the rest, and the order shuffled.
  std::vector<Item> items;
  for (const Entry& entry : entries) {
    if (random() % 3 != 0) items.push_back({entry.key});
    if (random() % 5 == 0) items.push_back({entry.key + 3});  // never a key of the last frame
  }
  std::shuffle(items.begin(), items.end(), random);

  KeyPlaces places;
  std::vector<Entry> scratch;
  ASSERT_TRUE(align_by_key(items, entries, places, scratch));
  ASSERT_EQ(entries.size(), items.size());
  for (size_t i = 0; i < items.size(); ++i) {
    EXPECT_EQ(entries[i].key, items[i].key);
    const auto before = value_of.find(items[i].key);
    EXPECT_EQ(entries[i].value, before == value_of.end() ? 0u : before->second) << items[i].key;
  }
  // The same keys in the same order again: nothing to do.
  EXPECT_FALSE(align_by_key(items, entries, places, scratch));
}

}  // namespace
}  // namespace sg::shadows
