// SPDX-License-Identifier: MIT
// Which casters changed since the last frame, as the boxes a cached shadow could have changed in.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "systems/shadows/caster_changes.h"

namespace sg::shadows {
namespace {

uint64_t key(uint32_t index, uint32_t generation = 0) { return uint64_t{generation} << 32 | index; }

scene::Aabb box_at(float x, float size = 1.0f) { return {glm::vec3(x, 0.0f, 0.0f), glm::vec3(x + size)}; }

bool same_box(const scene::Aabb& a, const scene::Aabb& b) { return a.min == b.min && a.max == b.max; }

bool reports(std::span<const scene::Aabb> changes, const scene::Aabb& box) {
  return std::any_of(changes.begin(), changes.end(), [&](const scene::Aabb& c) { return same_box(c, box); });
}

// Three casters at x = 0, 10, 20 in slots 0, 1, 2.
std::vector<CasterBounds> three_casters() {
  return {{key(0), box_at(0.0f)}, {key(1), box_at(10.0f)}, {key(2), box_at(20.0f)}};
}

TEST(CasterChangeTracker, TheFirstFrameReportsNothing) {
  CasterChangeTracker tracker;
  EXPECT_TRUE(tracker.update(three_casters()).empty());
}

TEST(CasterChangeTracker, AFrameWhereNothingMovedReportsNothing) {
  CasterChangeTracker tracker;
  tracker.update(three_casters());
  EXPECT_TRUE(tracker.update(three_casters()).empty());
  EXPECT_TRUE(tracker.update(three_casters()).empty());
}

TEST(CasterChangeTracker, AMovedCasterReportsItsOldAndItsNewBox) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters = three_casters();
  tracker.update(casters);
  casters[1].bounds = box_at(12.0f);
  const std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_TRUE(reports(changes, box_at(10.0f)));
  EXPECT_TRUE(reports(changes, box_at(12.0f)));
  // It stays where it is now: nothing more to report.
  EXPECT_TRUE(tracker.update(casters).empty());
}

TEST(CasterChangeTracker, AResizedCasterReportsItsOldAndItsNewBox) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters = three_casters();
  tracker.update(casters);
  casters[2].bounds = box_at(20.0f, 3.0f);
  const std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_TRUE(reports(changes, box_at(20.0f)));
  EXPECT_TRUE(reports(changes, box_at(20.0f, 3.0f)));
}

TEST(CasterChangeTracker, ANewCasterReportsItsBox) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters = three_casters();
  tracker.update(casters);
  casters.push_back({key(7), box_at(70.0f)});
  const std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_TRUE(same_box(changes[0], box_at(70.0f)));
}

TEST(CasterChangeTracker, ACasterOnOtherShadowLayersReportsItsBox) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters = three_casters();
  tracker.update(casters);
  casters[1].layers = 0x06;
  std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_TRUE(same_box(changes[0], casters[1].bounds));
  changes = tracker.update(casters);
  EXPECT_TRUE(changes.empty()) << "layers that stay are no change";
}

TEST(CasterChangeTracker, AGoneCasterReportsItsOldBox) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters = three_casters();
  tracker.update(casters);
  casters.erase(casters.begin());
  const std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_TRUE(same_box(changes[0], box_at(0.0f)));
  EXPECT_TRUE(tracker.update(casters).empty());
}

TEST(CasterChangeTracker, ACasterBackAfterAFrameAwayIsNewAgain) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters = three_casters();
  tracker.update(casters);
  tracker.update(std::span(casters).first(2));
  const std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_TRUE(same_box(changes[0], box_at(20.0f)));
}

TEST(CasterChangeTracker, ASlotReusedByANewEntityReportsTheOldCasterGoneAndTheNewOneNew) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters = three_casters();
  tracker.update(casters);
  // Entity (1, generation 0) destroyed, its slot reused by (1, generation 1) elsewhere.
  casters[1] = {key(1, 1), box_at(50.0f)};
  std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_TRUE(reports(changes, box_at(10.0f)));
  EXPECT_TRUE(reports(changes, box_at(50.0f)));

  // Even at the very same place: the new entity is a different caster.
  casters[1] = {key(1, 2), box_at(50.0f)};
  changes = tracker.update(casters);
  EXPECT_EQ(changes.size(), 2u);
}

TEST(CasterChangeTracker, TheOrderOfTheCastersDoesNotMatter) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters = three_casters();
  tracker.update(casters);
  std::reverse(casters.begin(), casters.end());
  EXPECT_TRUE(tracker.update(casters).empty());
  casters[0].bounds = box_at(25.0f);  // slot 2, after the reversal
  const std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_TRUE(reports(changes, box_at(20.0f)));
  EXPECT_TRUE(reports(changes, box_at(25.0f)));
}

TEST(CasterChangeTracker, EmptyBoxesAreNeverReported) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters = three_casters();
  tracker.update(casters);
  casters.push_back({key(5), scene::Aabb{}});
  EXPECT_TRUE(tracker.update(casters).empty());
  casters[0].bounds = scene::Aabb{};  // the caster at x = 0 lost its geometry
  const std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_TRUE(same_box(changes[0], box_at(0.0f)));
}

TEST(CasterChangeTracker, ManyCastersWithOneMovedReportTwoBoxes) {
  CasterChangeTracker tracker;
  std::vector<CasterBounds> casters;
  for (uint32_t i = 0; i < 20'000; ++i) casters.push_back({key(i, i % 3), box_at(float(i))});
  tracker.update(casters);
  casters[12'345].bounds = box_at(-1.0f);
  const std::span<const scene::Aabb> changes = tracker.update(casters);
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_TRUE(reports(changes, box_at(12'345.0f)));
  EXPECT_TRUE(reports(changes, box_at(-1.0f)));
}

}  // namespace
}  // namespace sg::shadows
