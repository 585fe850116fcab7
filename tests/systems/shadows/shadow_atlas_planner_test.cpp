// SPDX-License-Identifier: MIT
// The shadow atlas planner: resolutions from importance with hysteresis, the budget, tiles that
// persist across frames, repacking and the stats.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include "ecs/jobs/thread_pool.h"
#include "systems/shadows/shadow_atlas_pages.h"
#include "systems/shadows/shadow_atlas_planner.h"

namespace sg::shadows {
namespace {

// A request's placement with its tiles (ShadowAtlasPlanner::tiles_of), copied after the plan.
struct Placed {
  uint32_t resolution = 0;
  std::array<AtlasTile, 6> tiles{};
  bool moved = false;
};

std::vector<Placed> plan(ShadowAtlasPlanner& planner, const std::vector<ShadowRequest>& requests,
                         jobs::ThreadPool* pool = nullptr, float lowered_tiers = 0.0f, size_t slots = 0) {
  std::vector<ShadowPlacement> out(requests.size());
  planner.plan(requests, out, pool, lowered_tiers, slots);
  std::vector<Placed> placed(out.size());
  for (size_t i = 0; i < out.size(); ++i) {
    placed[i] = {out[i].resolution, {}, out[i].moved};
    if (out[i].resolution > 0) placed[i].tiles = planner.tiles_of(i);
  }
  return placed;
}

ShadowRequest map_light(uint64_t key, float importance, uint32_t max_resolution = 0) {
  return {.key = key, .cube = false, .max_resolution = max_resolution, .importance = importance};
}

ShadowRequest cube_light(uint64_t key, float importance) {
  return {.key = key, .cube = true, .max_resolution = 0, .importance = importance};
}

// Every tile inside a page below max_pages, aligned to its size, cube faces on one page, and no
// two tiles overlapping (checked on a grid of min_resolution cells per page).
void expect_valid_tiles(const AtlasConfig& config, const std::vector<ShadowRequest>& requests,
                        const std::vector<Placed>& placements) {
  const uint32_t cells = config.page_size / config.min_resolution;
  std::vector<uint8_t> used(size_t(config.max_pages) * cells * cells, 0);
  for (size_t i = 0; i < requests.size(); ++i) {
    const Placed& placement = placements[i];
    if (placement.resolution == 0) continue;
    const size_t tiles = requests[i].cube ? 6 : 1;
    for (size_t k = 0; k < tiles; ++k) {
      const AtlasTile& tile = placement.tiles[k];
      ASSERT_EQ(tile.size, placement.resolution);
      ASSERT_LT(tile.page, config.max_pages);
      ASSERT_EQ(tile.page, placement.tiles[0].page) << "cube faces share a page";
      ASSERT_EQ(tile.x % tile.size, 0u);
      ASSERT_EQ(tile.y % tile.size, 0u);
      ASSERT_LE(tile.x + tile.size, config.page_size);
      ASSERT_LE(tile.y + tile.size, config.page_size);
      for (uint32_t y = tile.y / config.min_resolution; y < (tile.y + tile.size) / config.min_resolution;
           ++y) {
        for (uint32_t x = tile.x / config.min_resolution; x < (tile.x + tile.size) / config.min_resolution;
             ++x) {
          uint8_t& cell = used[(size_t(tile.page) * cells + y) * cells + x];
          ASSERT_EQ(cell, 0) << "tiles overlap on page " << tile.page << " at cell " << x << ", " << y;
          cell = 1;
        }
      }
    }
  }
}

TEST(ShadowAtlasPages, ClaimTakesBackExactlyATileThatIsFree) {
  ShadowAtlasPages pages(128, 32, 1);
  std::array<AtlasTile, 4> quarters{};
  ASSERT_TRUE(pages.allocate(64, quarters));
  pages.free(quarters[2]);
  EXPECT_FALSE(pages.claim(quarters[1])) << "taken";
  EXPECT_FALSE(pages.claim({0, 0, 0, 128})) << "partly taken";
  EXPECT_FALSE(pages.claim({1, 0, 0, 64})) << "no such page";
  EXPECT_TRUE(pages.claim(quarters[2]));
  std::array<AtlasTile, 1> more{};
  EXPECT_FALSE(pages.allocate(32, more)) << "the page is full again";
  pages.free(quarters[0]);
  EXPECT_TRUE(pages.claim({0, quarters[0].x + 32, quarters[0].y, 32})) << "a quarter of a free tile";
  EXPECT_TRUE(pages.allocate(32, more));
  EXPECT_EQ(more[0].x / 64, quarters[0].x / 64);
  EXPECT_EQ(more[0].y / 64, quarters[0].y / 64);
}

// The planner's AtlasStats::pages_used comes from here.
TEST(ShadowAtlasPages, PagesUsedEndAtTheHighestPageHoldingATile) {
  ShadowAtlasPages pages(128, 32, 3);
  EXPECT_EQ(pages.pages_used(), 0u);
  std::array<AtlasTile, 1> first{}, second{}, third{};
  ASSERT_TRUE(pages.allocate(128, first));
  ASSERT_TRUE(pages.allocate(64, second));
  ASSERT_TRUE(pages.allocate(128, third));
  ASSERT_EQ(third[0].page, 2u);
  EXPECT_EQ(pages.pages_used(), 3u);
  pages.free(third[0]);
  EXPECT_EQ(pages.pages_used(), 2u) << "the last page is free again";
  pages.free(first[0]);
  EXPECT_EQ(pages.pages_used(), 2u) << "a free page below a used one";
  pages.free(second[0]);
  EXPECT_EQ(pages.pages_used(), 0u);
  ASSERT_TRUE(pages.allocate(32, first));
  pages.clear();
  EXPECT_EQ(pages.pages_used(), 0u);
}

TEST(ShadowAtlasPlanner, ResolutionIsImportanceRoundedToAPowerOfTwoWithinLimits) {
  ShadowAtlasPlanner planner({.page_size = 4096, .max_pages = 64, .min_resolution = 32});
  const std::vector<ShadowRequest> requests{
      map_light(1, 300.0f),        map_light(2, 400.0f), map_light(3, 2000.0f, 700), map_light(4, 1.0f),
      map_light(5, 1e9f),          cube_light(6, 1e9f),  map_light(7, 10.0f, 8),     cube_light(8, 100.0f),
      map_light(9, std::nanf("")), map_light(10, -5.0f)};
  const std::vector<Placed> out = plan(planner, requests);
  EXPECT_EQ(out[0].resolution, 256u);
  EXPECT_EQ(out[1].resolution, 512u);
  EXPECT_EQ(out[2].resolution, 512u) << "max_resolution rounds down to a power of two";
  EXPECT_EQ(out[3].resolution, 32u) << "never below min_resolution";
  EXPECT_EQ(out[4].resolution, 4096u) << "never above the page";
  EXPECT_EQ(out[5].resolution, 1024u) << "six faces must fit one page";
  EXPECT_EQ(out[6].resolution, 32u) << "min_resolution wins over a smaller max_resolution";
  EXPECT_EQ(out[7].resolution, 128u);
  EXPECT_EQ(out[8].resolution, 32u);
  EXPECT_EQ(out[9].resolution, 32u);
}

// ShadowResolution::requested: a pinned light wants its cap however small it is on screen, and
// its importance still decides who the budget demotes first.
TEST(ShadowAtlasPlanner, PinnedLightsWantTheirCapAndTheBudgetStillDemotesByImportance) {
  ShadowRequest far_map = map_light(1, 3.0f, 2048);
  ShadowRequest far_cube = cube_light(2, 3.0f);
  far_map.pinned = far_cube.pinned = true;
  ShadowAtlasPlanner roomy({.page_size = 4096, .max_pages = 4, .min_resolution = 16});
  const std::vector<Placed> out = plan(roomy, {far_map, far_cube});
  EXPECT_EQ(out[0].resolution, 2048u);
  EXPECT_EQ(out[1].resolution, 1024u) << "a cube's cap: six faces on one page";

  // A 1024 and a 512 map overfill a 1024 page: the less important (the large one) drops a tier;
  // had the other dropped first, it would have gone to 256 and the large one to 512 after it.
  ShadowAtlasPlanner tight({.page_size = 1024, .max_pages = 1, .min_resolution = 16});
  ShadowRequest large = map_light(1, 3.0f, 1024), small = map_light(2, 5.0f, 512);
  large.pinned = small.pinned = true;
  const std::vector<Placed> squeezed = plan(tight, {large, small});
  EXPECT_EQ(squeezed[0].resolution, 512u);
  EXPECT_EQ(squeezed[1].resolution, 512u);
  EXPECT_EQ(tight.stats().demoted_by_budget, 1u);
}

TEST(ShadowAtlasPlanner, SmallImportanceOscillationsKeepTheResolutionLargeOnesChangeIt) {
  ShadowAtlasPlanner planner({.page_size = 4096, .max_pages = 4, .min_resolution = 32});
  ASSERT_EQ(plan(planner, {map_light(1, 256.0f)})[0].resolution, 256u);
  // 2^+-0.6 around 256 would round to 512 and 128 without hysteresis.
  for (int frame = 0; frame < 20; ++frame) {
    const float importance = 256.0f * std::exp2(frame % 2 ? 0.6f : -0.6f);
    const Placed placement = plan(planner, {map_light(1, importance)})[0];
    EXPECT_EQ(placement.resolution, 256u) << "frame " << frame;
    EXPECT_FALSE(placement.moved);
  }
  const Placed up = plan(planner, {map_light(1, 256.0f * std::exp2(0.8f))})[0];
  EXPECT_EQ(up.resolution, 512u);
  EXPECT_TRUE(up.moved);
  // Now held at 512: 2^-0.6 below it stays, a whole tier down goes.
  EXPECT_EQ(plan(planner, {map_light(1, 512.0f * std::exp2(-0.6f))})[0].resolution, 512u);
  EXPECT_EQ(plan(planner, {map_light(1, 256.0f)})[0].resolution, 256u);
  EXPECT_EQ(plan(planner, {map_light(1, 2048.0f)})[0].resolution, 2048u);
}

// lights_changed_tier counts the lights placed in the previous plan whose resolution differs:
// not new lights, not lights held by the hysteresis.
TEST(ShadowAtlasPlanner, CountsTheLightsThatChangedTier) {
  ShadowAtlasPlanner planner({.page_size = 4096, .max_pages = 4, .min_resolution = 32});
  plan(planner, {map_light(1, 256.0f), map_light(2, 256.0f)});
  EXPECT_EQ(planner.stats().lights_changed_tier, 0u) << "new lights";
  plan(planner, {map_light(1, 256.0f * std::exp2(0.6f)), map_light(2, 2048.0f)});
  EXPECT_EQ(planner.stats().lights_changed_tier, 1u) << "light 2 up three tiers, light 1 held";
  plan(planner, {map_light(1, 256.0f), map_light(2, 64.0f), map_light(3, 64.0f)});
  EXPECT_EQ(planner.stats().lights_changed_tier, 1u) << "light 2 down; light 3 is new";
  plan(planner, {map_light(1, 256.0f), map_light(2, 64.0f), map_light(3, 64.0f)});
  EXPECT_EQ(planner.stats().lights_changed_tier, 0u);
}

// The time budget's lowered tiers: every light as if log2 of what it gets were that much lower,
// never below its quality floor, and a light that wants less than its floor keeps what it wants.
TEST(ShadowAtlasPlanner, LoweredTiersLowerEveryLightDownToItsFloor) {
  ShadowAtlasPlanner planner({.page_size = 4096, .max_pages = 64, .min_resolution = 32});
  std::vector<ShadowRequest> requests{map_light(1, 1024.0f),     map_light(2, 512.0f), map_light(3, 128.0f),
                                      map_light(4, 40.0f),       map_light(5, 1e9f),   cube_light(6, 1e9f),
                                      map_light(7, 2000.0f, 256)};
  for (ShadowRequest& request : requests) request.quality_floor = 128;
  ShadowRequest pinned = map_light(8, 3.0f, 512);
  pinned.pinned = true;
  requests.push_back(pinned);
  std::vector<Placed> out = plan(planner, requests, nullptr, 2.0f);
  EXPECT_EQ(out[0].resolution, 256u);
  EXPECT_EQ(out[1].resolution, 128u);
  EXPECT_EQ(out[2].resolution, 128u) << "at its floor already";
  EXPECT_EQ(out[3].resolution, 32u) << "below its floor anyway: as its importance asks";
  EXPECT_EQ(out[4].resolution, 1024u) << "lowered from the page it gets, not its importance";
  EXPECT_EQ(out[5].resolution, 256u) << "a cube's cap is a quarter page";
  EXPECT_EQ(out[6].resolution, 128u) << "lowered from its own cap";
  EXPECT_EQ(out[7].resolution, 512u) << "pinned";
  const AtlasStats& stats = planner.stats();
  EXPECT_EQ(stats.demoted_by_time, 5u);
  EXPECT_EQ(stats.lowerable_by_time, 3u) << "the 256 map and the 1024 map and cube";
  EXPECT_EQ(stats.demoted_by_budget, 0u) << "the memory budget did none of it";

  // Without lowered tiers, each light is back at what its importance asks at once.
  out = plan(planner, requests);
  EXPECT_EQ(out[0].resolution, 1024u);
  EXPECT_EQ(out[4].resolution, 4096u);
  EXPECT_EQ(planner.stats().demoted_by_time, 0u);
  EXPECT_EQ(planner.stats().lowerable_by_time, 5u);
}

// Under redraw_cost a map kept from frame to frame is spared the lowered tiers (a third of log2
// of how seldom it is redrawn, at most most_spared_tiers) and does not count as lowerable: lower
// tiers would save no time. Uniform lowers it all the same.
TEST(ShadowAtlasPlanner, RedrawCostSparesMapsKeptFromFrameToFrame) {
  for (const ShadowTimePolicy policy : {ShadowTimePolicy::redraw_cost, ShadowTimePolicy::uniform}) {
    ShadowAtlasPlanner planner({.page_size = 4096, .max_pages = 4, .min_resolution = 32}, policy);
    std::vector<ShadowRequest> requests{map_light(1, 1024.0f), map_light(2, 1024.0f)};
    for (ShadowRequest& request : requests) request.quality_floor = 64;
    std::vector<Placed> out(requests.size());
    const std::vector<uint8_t> redraws{ShadowAtlasPlanner::map_redrawn, ShadowAtlasPlanner::map_kept};
    for (int frame = 0; frame < 200; ++frame) {
      out = plan(planner, requests);
      planner.record_redraws(redraws);
    }
    out = plan(planner, requests, nullptr, 2.0f);
    EXPECT_EQ(out[0].resolution, 256u) << "redrawn every frame: lowered";
    if (policy == ShadowTimePolicy::redraw_cost) {
      EXPECT_EQ(out[1].resolution, 1024u) << "kept: spared";
      EXPECT_EQ(planner.stats().lowerable_by_time, 1u);
      EXPECT_EQ(planner.stats().demoted_by_time, 1u);
    } else {
      EXPECT_EQ(out[1].resolution, 256u) << "uniform";
      EXPECT_EQ(planner.stats().lowerable_by_time, 2u);
      EXPECT_EQ(planner.stats().demoted_by_time, 2u);
    }
    // A light that starts moving pays its way again within a few dozen frames (to within the
    // backlash of its held tiers).
    const std::vector<uint8_t> both_redrawn{ShadowAtlasPlanner::map_redrawn, ShadowAtlasPlanner::map_redrawn};
    for (int frame = 0; frame < 60; ++frame) {
      out = plan(planner, requests, nullptr, 2.0f);
      planner.record_redraws(both_redrawn);
    }
    EXPECT_LE(out[1].resolution, 512u);
  }
}

TEST(ShadowAtlasPlanner, LoweredTiersIgnoreWobblingImportancesAndStepBackExactly) {
  ShadowAtlasPlanner planner({.page_size = 4096, .max_pages = 4, .min_resolution = 32});
  const auto lowered = [&](float importance, float tiers) {
    std::vector<Placed> out =
        plan(planner, std::vector<ShadowRequest>{map_light(1, importance)}, nullptr, tiers);
    return out[0].resolution;
  };
  // 10.5 tiers lowered by 1: 9.5, on the boundary between 512 and 1024.
  const float boundary = std::exp2(10.5f);
  ASSERT_EQ(lowered(boundary, 1.0f), 1024u);
  for (int frame = 0; frame < 20; ++frame) {
    EXPECT_EQ(lowered(boundary * std::exp2(frame % 2 ? 0.6f : -0.6f), 1.0f), 1024u) << "frame " << frame;
  }
  // Each number of lowered tiers gives its resolution whatever came before.
  EXPECT_EQ(lowered(boundary, 1.25f), 512u);
  EXPECT_EQ(lowered(boundary, 2.25f), 256u);
  EXPECT_EQ(lowered(boundary, 1.25f), 512u);
  EXPECT_EQ(lowered(boundary, 1.0f), 1024u);
  EXPECT_EQ(lowered(boundary, 0.0f), 2048u);
  // A light that moves a whole tier nearer moves its held tiers along.
  EXPECT_EQ(lowered(boundary * 2.0f, 1.25f), 1024u);
}

TEST(ShadowAtlasPlanner, OverBudgetTheLeastImportantLightsDropATierFirst) {
  const AtlasConfig config{.page_size = 1024, .max_pages = 1, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  // Eight lights that want 512 (two pages' worth), light i more important than light i - 1.
  std::vector<ShadowRequest> requests;
  for (uint64_t i = 0; i < 8; ++i) requests.push_back(map_light(i, 512.0f + 5.0f * float(i)));
  std::reverse(requests.begin(), requests.end());  // the order of requests does not matter
  const std::vector<Placed> out = plan(planner, requests);
  expect_valid_tiles(config, requests, out);
  for (size_t r = 0; r < requests.size(); ++r) {
    EXPECT_EQ(out[r].resolution, requests[r].key >= 6 ? 512u : 256u) << "light " << requests[r].key;
  }
  const AtlasStats& stats = planner.stats();
  EXPECT_EQ(stats.pages_used, 1u);
  EXPECT_EQ(stats.texels_used, 2u * 512u * 512u + 6u * 256u * 256u);
  EXPECT_EQ(stats.lights_per_resolution, (std::vector<std::pair<uint32_t, uint32_t>>{{512, 2}, {256, 6}}));
  EXPECT_EQ(stats.demoted_by_budget, 6u);
  EXPECT_EQ(stats.lights_without_shadow, 0u);
}

TEST(ShadowAtlasPlanner, OverBudgetLightsAboveTheirQualityFloorDropFirst) {
  const AtlasConfig config{.page_size = 1024, .max_pages = 1, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  // Four lights wanting 512 fill the page; the least important light wants 256 and its
  // algorithm needs all of it. Without floors it would drop to 128 first.
  std::vector<ShadowRequest> requests{map_light(0, 256.0f)};
  requests[0].quality_floor = 256;
  for (uint64_t i = 1; i <= 4; ++i) {
    requests.push_back(map_light(i, 512.0f + 5.0f * float(i)));
    requests.back().quality_floor = 64;
  }
  const std::vector<Placed> out = plan(planner, requests);
  expect_valid_tiles(config, requests, out);
  EXPECT_EQ(out[0].resolution, 256u) << "kept at its floor";
  EXPECT_EQ(out[1].resolution, 256u) << "the least important of the lights above their floors";
  for (size_t r = 2; r < requests.size(); ++r) EXPECT_EQ(out[r].resolution, 512u) << "light " << r;
}

TEST(ShadowAtlasPlanner, WhenEveryLightIsAtItsFloorTheBudgetStillFits) {
  const AtlasConfig config{.page_size = 1024, .max_pages = 1, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  // Eight lights that want 512 and need 512: two pages' worth, so floors give way, least
  // important first, as without them.
  std::vector<ShadowRequest> requests;
  for (uint64_t i = 0; i < 8; ++i) {
    requests.push_back(map_light(i, 512.0f + 5.0f * float(i)));
    requests.back().quality_floor = 512;
  }
  const std::vector<Placed> out = plan(planner, requests);
  expect_valid_tiles(config, requests, out);
  for (size_t r = 0; r < requests.size(); ++r) EXPECT_EQ(out[r].resolution, r >= 6 ? 512u : 256u) << r;
}

TEST(ShadowAtlasPlanner, OnceAllAreAtTheSmallestTileTheLeastImportantLoseTheirShadow) {
  const AtlasConfig config{.page_size = 256, .max_pages = 1, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  // 100 lights wanting 64 where the page holds 64 tiles of 32.
  std::vector<ShadowRequest> requests;
  for (uint64_t i = 0; i < 100; ++i) requests.push_back(map_light(i, 64.0f + 0.1f * float(i)));
  const std::vector<Placed> out = plan(planner, requests);
  expect_valid_tiles(config, requests, out);
  for (size_t i = 0; i < requests.size(); ++i) EXPECT_EQ(out[i].resolution, i < 36 ? 0u : 32u) << i;
  EXPECT_EQ(planner.stats().lights_without_shadow, 36u);
  EXPECT_EQ(planner.stats().dropped_by_budget, 36u);
  EXPECT_EQ(planner.stats().demoted_by_budget, 64u);
}

TEST(ShadowAtlasPlanner, HundredThousandLightsAreDemotedByImportanceWithoutOverlaps) {
  const AtlasConfig config{.page_size = 4096, .max_pages = 4, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> tiers(0.0f, 12.0f);
  std::vector<ShadowRequest> requests;
  for (uint64_t i = 0; i < 100'000; ++i) {
    const float importance = std::exp2(tiers(random));
    requests.push_back(i % 10 == 0 ? cube_light(i, importance) : map_light(i, importance));
  }
  const std::vector<Placed> out = plan(planner, requests);
  expect_valid_tiles(config, requests, out);
  EXPECT_GT(planner.stats().lights_without_shadow, 0u);
  // A more important light never has a smaller map than a less important one of its kind.
  for (const bool cube : {false, true}) {
    std::vector<std::pair<float, uint32_t>> by_importance;
    for (size_t i = 0; i < requests.size(); ++i) {
      if (requests[i].cube == cube) by_importance.emplace_back(requests[i].importance, out[i].resolution);
    }
    std::sort(by_importance.begin(), by_importance.end());
    for (size_t k = 1; k < by_importance.size(); ++k) {
      ASSERT_GE(by_importance[k].second, by_importance[k - 1].second) << "cube " << cube;
    }
  }
  // A second frame with every importance a little different.
  for (ShadowRequest& request : requests) request.importance *= 1.1f;
  expect_valid_tiles(config, requests, plan(planner, requests));
}

// The budget's rule walked one light at a time, as a model: passes from the least important
// light up, each halving every light above its floor (its quality floor, then the smallest tile),
// until the demotions so far save what did not fit and the tiles then pack (largest first, cubes
// before maps, each on the lowest page with room); once all are at the smallest tile, the least
// important lose their shadow. Takes the resolutions wanted, least important first.
std::vector<uint32_t> fit_light_by_light(const AtlasConfig& config,
                                         const std::vector<ShadowRequest>& requests,
                                         std::vector<uint32_t> resolution) {
  const auto tier = [&](uint32_t side) { return std::countr_zero(config.page_size / side); };
  const auto does_not_fit = [&] {
    std::vector<uint64_t> free(config.max_pages, 1);
    uint64_t unplaced = 0;
    for (int t = 0; config.page_size >> t >= config.min_resolution; ++t) {
      if (t > 0) {
        for (uint64_t& room : free) room *= 4;
      }
      uint64_t cubes = 0, maps = 0;
      for (size_t i = 0; i < requests.size(); ++i) {
        if (resolution[i] > 0 && tier(resolution[i]) == t) ++(requests[i].cube ? cubes : maps);
      }
      for (uint64_t& room : free) {
        const uint64_t placed = std::min(cubes, room / 6);
        room -= 6 * placed;
        cubes -= placed;
      }
      for (uint64_t& room : free) {
        const uint64_t placed = std::min(maps, room);
        room -= placed;
        maps -= placed;
      }
      unplaced += (6 * cubes + maps) * uint64_t(config.page_size >> t) * (config.page_size >> t);
    }
    return unplaced;
  };
  const auto saving = [&](size_t i, uint32_t to) {
    return (requests[i].cube ? 6u : 1u) * (uint64_t(resolution[i]) * resolution[i] - uint64_t(to) * to);
  };
  for (int stage = 0; stage < 3;) {
    bool demoted = false;
    for (size_t i = 0; i < requests.size(); ++i) {
      const uint64_t excess = does_not_fit();
      if (excess == 0) return resolution;
      // Steps until they save the excess, then the packing is checked again.
      for (uint64_t saved = 0; saved < excess && i < requests.size(); ++i) {
        if (stage == 2) {
          saved += saving(i, 0);
          resolution[i] = 0;
          continue;
        }
        const uint32_t floor =
            stage == 0 ? std::max(config.min_resolution, requests[i].quality_floor) : config.min_resolution;
        if (resolution[i] / 2 < floor) continue;
        saved += saving(i, resolution[i] / 2);
        resolution[i] /= 2;
        demoted = true;
      }
      --i;
    }
    if (!demoted) ++stage;
  }
  return resolution;
}

TEST(ShadowAtlasPlanner, TheBudgetDemotesAsWalkingItsPassesLightByLightWould) {
  const AtlasConfig config{.page_size = 2048, .max_pages = 2, .min_resolution = 16};
  std::mt19937 random(11);
  std::uniform_int_distribution<int> tiers(4, 11);
  std::uniform_int_distribution<int> floors(0, 3);
  jobs::ThreadPool threads(3);
  for (const size_t count : {40u, 700u, 3000u, 10'000u}) {
    // Importances that are whole powers of two, so each light wants exactly that resolution.
    std::vector<ShadowRequest> requests;
    for (uint64_t i = 0; i < count; ++i) {
      const float importance = std::exp2(float(tiers(random)));
      requests.push_back(i % 7 == 0 ? cube_light(i, std::min(importance, 512.0f)) : map_light(i, importance));
      requests.back().quality_floor = 16u << floors(random);
    }
    // Least important first, ties by key, as the planner orders them.
    std::stable_sort(requests.begin(), requests.end(), [](const ShadowRequest& a, const ShadowRequest& b) {
      return a.importance < b.importance;
    });
    std::vector<uint32_t> wanted;
    for (const ShadowRequest& request : requests) wanted.push_back(uint32_t(request.importance));
    const std::vector<uint32_t> expected = fit_light_by_light(config, requests, wanted);
    // Asked in a shuffled order: the planner finds the order itself. On one thread and on a pool.
    std::vector<size_t> asked(requests.size());
    std::iota(asked.begin(), asked.end(), size_t{0});
    std::shuffle(asked.begin(), asked.end(), random);
    std::vector<ShadowRequest> shuffled;
    for (const size_t i : asked) shuffled.push_back(requests[i]);
    for (jobs::ThreadPool* pool : {static_cast<jobs::ThreadPool*>(nullptr), &threads}) {
      ShadowAtlasPlanner planner(config);
      std::vector<Placed> out = plan(planner, shuffled, pool);
      expect_valid_tiles(config, shuffled, out);
      for (size_t k = 0; k < asked.size(); ++k) {
        ASSERT_EQ(out[k].resolution, expected[asked[k]])
            << count << " lights, light " << asked[k] << (pool ? ", on a pool" : "");
      }
    }
  }
}

TEST(ShadowAtlasPlanner, UnchangedLightsKeepTheirTilesNewAndChangedOnesMove) {
  const AtlasConfig config{.page_size = 1024, .max_pages = 4, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  std::vector<ShadowRequest> requests{map_light(1, 256.0f), cube_light(2, 64.0f), map_light(3, 512.0f),
                                      map_light(4, 32.0f)};
  const std::vector<Placed> first = plan(planner, requests);
  for (const Placed& placement : first) EXPECT_TRUE(placement.moved);

  // Reordered, with a new light and light 3 a tier down.
  std::vector<ShadowRequest> next{map_light(5, 128.0f), map_light(4, 32.0f), map_light(3, 256.0f),
                                  cube_light(2, 64.0f), map_light(1, 256.0f)};
  const std::vector<Placed> second = plan(planner, next);
  expect_valid_tiles(config, next, second);
  EXPECT_TRUE(second[0].moved);
  EXPECT_FALSE(second[1].moved);
  EXPECT_EQ(second[1].tiles, first[3].tiles);
  EXPECT_TRUE(second[2].moved);
  EXPECT_EQ(second[2].resolution, 256u);
  EXPECT_FALSE(second[3].moved);
  EXPECT_EQ(second[3].tiles, first[1].tiles);
  EXPECT_FALSE(second[4].moved);
  EXPECT_EQ(second[4].tiles, first[0].tiles);
}

// Matching requests to last plan's lights by their place (on the pool) and by key (after) must
// still give a key asked for twice one shadow, whichever request came where last time.
TEST(ShadowAtlasPlanner, AKeyRequestedTwiceGetsOneShadow) {
  const AtlasConfig config{.page_size = 1024, .max_pages = 1, .min_resolution = 32};
  jobs::ThreadPool threads(3);
  for (jobs::ThreadPool* pool : {static_cast<jobs::ThreadPool*>(nullptr), &threads}) {
    ShadowAtlasPlanner planner(config);
    std::vector<ShadowRequest> requests;
    for (uint64_t key = 0; key < 200; ++key) requests.push_back(map_light(key, 32.0f));
    for (int frame = 0; frame < 3; ++frame) {
      std::vector<Placed> out = plan(planner, requests, pool);
      expect_valid_tiles(config, requests, out);
      std::map<uint64_t, int> shadows_of_key;
      for (size_t i = 0; i < requests.size(); ++i) shadows_of_key[requests[i].key] += out[i].resolution > 0;
      for (const auto& [key, shadows] : shadows_of_key)
        EXPECT_EQ(shadows, 1) << "key " << key << " frame " << frame;
      EXPECT_EQ(planner.stats().lights_without_shadow, requests.size() - shadows_of_key.size());
      // Next frame: key 7 asked for again, ahead of its own earlier place and behind it.
      requests.insert(requests.begin() + 3, map_light(7, 32.0f));
      requests.push_back(map_light(150, 32.0f));
    }
  }
}

TEST(ShadowAtlasPlanner, LightsThatVanishFreeTheirTiles) {
  const AtlasConfig config{.page_size = 256, .max_pages = 1, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  // Four lights of 128 fill the page.
  std::vector<ShadowRequest> requests;
  for (uint64_t key = 0; key < 4; ++key) requests.push_back(map_light(key, 128.0f));
  const std::vector<Placed> first = plan(planner, requests);
  requests[2] = map_light(9, 128.0f);
  const std::vector<Placed> second = plan(planner, requests);
  EXPECT_EQ(second[2].resolution, 128u);
  EXPECT_TRUE(second[2].moved);
  EXPECT_EQ(second[2].tiles[0], first[2].tiles[0]) << "the new light takes the vanished one's tile";
  for (const size_t i : {0, 1, 3}) {
    EXPECT_FALSE(second[i].moved);
    EXPECT_EQ(second[i].tiles, first[i].tiles);
  }
}

// Sixteen lights of 64 fill a 256 page; keeping those right of every 128 square's middle frees
// half the page, but no 128 square. `before` gets the kept lights' tiles.
std::vector<ShadowRequest> half_page_in_strips(ShadowAtlasPlanner& planner,
                                               std::map<uint64_t, AtlasTile>& before) {
  std::vector<ShadowRequest> requests;
  for (uint64_t key = 0; key < 16; ++key) requests.push_back(map_light(key, 64.0f));
  const std::vector<Placed> full = plan(planner, requests);
  std::vector<ShadowRequest> kept;
  for (size_t i = 0; i < requests.size(); ++i) {
    if (full[i].tiles[0].x % 128 != 0) {
      kept.push_back(requests[i]);
      before[requests[i].key] = full[i].tiles[0];
    }
  }
  plan(planner, kept);
  return kept;
}

TEST(ShadowAtlasPlanner, ANewLightFindingNoFreeTileOfItsSizeTakesASmallerOneAndNoOtherMoves) {
  const AtlasConfig config{.page_size = 256, .max_pages = 1, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  std::map<uint64_t, AtlasTile> before;
  std::vector<ShadowRequest> kept = half_page_in_strips(planner, before);
  ASSERT_EQ(kept.size(), 8u);
  kept.push_back(map_light(100, 128.0f));
  const std::vector<Placed> out = plan(planner, kept);
  expect_valid_tiles(config, kept, out);
  EXPECT_EQ(out.back().resolution, 64u) << "the largest free tile";
  EXPECT_TRUE(out.back().moved);
  for (size_t i = 0; i + 1 < kept.size(); ++i) {
    EXPECT_FALSE(out[i].moved) << "light " << kept[i].key;
    EXPECT_EQ(out[i].tiles[0], before[kept[i].key]);
  }
  EXPECT_EQ(planner.stats().held_back_by_free_space, 1u);
  EXPECT_EQ(planner.stats().demoted_by_budget, 1u);
  EXPECT_EQ(planner.stats().lights_retiled, 1u);
  EXPECT_FALSE(planner.stats().repacked);
}

TEST(ShadowAtlasPlanner, ALightGoingUpKeepsItsMapUntilALargerTileIsFree) {
  const AtlasConfig config{.page_size = 256, .max_pages = 1, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  std::map<uint64_t, AtlasTile> before;
  std::vector<ShadowRequest> kept = half_page_in_strips(planner, before);
  kept.front().importance = 128.0f;
  std::vector<Placed> out = plan(planner, kept);
  EXPECT_EQ(out.front().resolution, 64u);
  EXPECT_FALSE(out.front().moved) << "its map stays valid";
  EXPECT_EQ(out.front().tiles[0], before[kept.front().key]);
  EXPECT_EQ(planner.stats().held_back_by_free_space, 1u);
  EXPECT_EQ(planner.stats().lights_retiled, 0u);

  // Its neighbour in the 128 square goes: now there is room.
  const AtlasTile own = before[kept.front().key];
  const auto neighbour = std::find_if(kept.begin() + 1, kept.end(), [&](const ShadowRequest& request) {
    const AtlasTile& tile = before[request.key];
    return tile.x / 128 == own.x / 128 && tile.y / 128 == own.y / 128;
  });
  ASSERT_NE(neighbour, kept.end());
  kept.erase(neighbour);
  out = plan(planner, kept);
  expect_valid_tiles(config, kept, out);
  EXPECT_EQ(out.front().resolution, 128u);
  EXPECT_TRUE(out.front().moved);
  EXPECT_EQ(planner.stats().held_back_by_free_space, 0u);
  EXPECT_FALSE(planner.stats().repacked);
}

TEST(ShadowAtlasPlanner, OnlyWhenNotEvenTheSmallestTilesFitIsEverythingRepacked) {
  // Two pages of 4 x 4 smallest tiles; 13 maps on each leave 3 free a page: the 6 a cube of the
  // smallest tiles needs are free, but not on one page.
  const AtlasConfig config{.page_size = 128, .max_pages = 2, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  std::vector<ShadowRequest> requests;
  for (uint64_t key = 0; key < 32; ++key) requests.push_back(map_light(key, 32.0f));
  std::vector<Placed> out = plan(planner, requests);
  std::vector<ShadowRequest> kept;
  uint32_t freed_on[2] = {0, 0};
  for (size_t i = 0; i < requests.size(); ++i) {
    uint32_t& freed = freed_on[out[i].tiles[0].page];
    if (freed < 3) {
      ++freed;
      continue;
    }
    kept.push_back(requests[i]);
  }
  ASSERT_EQ(kept.size(), 26u);
  plan(planner, kept);
  EXPECT_FALSE(planner.stats().repacked);
  kept.push_back(cube_light(100, 32.0f));
  out = plan(planner, kept);
  expect_valid_tiles(config, kept, out);
  EXPECT_TRUE(planner.stats().repacked);
  EXPECT_EQ(out.back().resolution, 32u) << "the area fits: repacked, the cube has its shadow";
  EXPECT_GT(planner.stats().lights_retiled, 1u) << "the maps that moved say so";
}

TEST(ShadowAtlasPlanner, RandomChurnNeverOverlapsAndMovedMeansNewTiles) {
  const AtlasConfig config{.page_size = 1024, .max_pages = 3, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  constexpr uint64_t key_count = 200;
  std::vector<bool> active(key_count, false);
  std::vector<float> importance(key_count);
  for (float& value : importance) value = std::exp2(4.0f + 7.0f * unit(random));
  std::map<uint64_t, Placed> last;
  size_t kept_tiles = 0;
  for (int frame = 0; frame < 400; ++frame) {
    std::vector<ShadowRequest> requests;
    for (uint64_t key = 0; key < key_count; ++key) {
      if (unit(random) < 0.03f) active[key] = !active[key];
      if (!active[key]) continue;
      // Mostly small drifts, now and then a jump.
      importance[key] *=
          unit(random) < 0.02f ? std::exp2(4.0f * unit(random) - 2.0f) : 0.95f + 0.1f * unit(random);
      importance[key] = std::clamp(importance[key], 1.0f, 4096.0f);
      requests.push_back({.key = key,
                          .cube = key % 5 == 0,
                          .max_resolution = key % 7 == 0 ? 256u : 0u,
                          .importance = importance[key]});
    }
    std::shuffle(requests.begin(), requests.end(), random);
    const std::vector<Placed> out = plan(planner, requests);
    expect_valid_tiles(config, requests, out);
    if (HasFatalFailure()) return;

    std::map<uint64_t, Placed> now;
    uint32_t pages_used = 0, without_shadow = 0;
    uint64_t texels = 0;
    for (size_t i = 0; i < requests.size(); ++i) {
      const Placed& placement = out[i];
      now[requests[i].key] = placement;
      if (placement.resolution == 0) {
        ++without_shadow;
        continue;
      }
      pages_used = std::max(pages_used, placement.tiles[0].page + 1);
      texels += (requests[i].cube ? 6u : 1u) * uint64_t(placement.resolution) * placement.resolution;
      const auto previous = last.find(requests[i].key);
      const bool same = previous != last.end() && previous->second.resolution == placement.resolution &&
                        previous->second.tiles == placement.tiles;
      EXPECT_EQ(placement.moved, !same) << "frame " << frame << " light " << requests[i].key;
      kept_tiles += same;
    }
    EXPECT_EQ(planner.stats().pages_used, pages_used);
    EXPECT_EQ(planner.stats().texels_used, texels);
    EXPECT_EQ(planner.stats().lights_without_shadow, without_shadow);
    last = std::move(now);
  }
  EXPECT_GT(kept_tiles, 0u);
}

// Churn for the tests that plan one way against another: 600 lights, a tenth of them out of sight
// each frame (every later request moves), importances jumping now and then, a third cubes.
class Churn {
 public:
  explicit Churn(unsigned seed) : random_(seed), importance_(600) {
    for (float& value : importance_) value = std::exp2(4.0f + 7.0f * unit_(random_));
  }
  size_t lights() const { return importance_.size(); }
  // The next frame's requests, each light's slot from `slot_of_key` where given.
  std::vector<ShadowRequest> next(std::span<const uint32_t> slot_of_key = {}) {
    std::vector<ShadowRequest> requests;
    for (uint64_t key = 0; key < importance_.size(); ++key) {
      if (unit_(random_) < 0.1f) continue;  // out of sight this frame
      importance_[key] = std::clamp(
          importance_[key] * (unit_(random_) < 0.05f ? 4.0f * unit_(random_) : 1.0f), 1.0f, 4096.0f);
      requests.push_back({.key = key,
                          .cube = key % 3 == 0,
                          .importance = importance_[key],
                          .slot = slot_of_key.empty() ? 0u : slot_of_key[key]});
    }
    return requests;
  }

 private:
  std::mt19937 random_;
  std::uniform_real_distribution<float> unit_{0.0f, 1.0f};
  std::vector<float> importance_;
};

void expect_same_placements(const std::vector<Placed>& got, const std::vector<Placed>& expected, int frame) {
  ASSERT_EQ(got.size(), expected.size());
  for (size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i].resolution, expected[i].resolution) << "frame " << frame << " request " << i;
    ASSERT_EQ(got[i].tiles, expected[i].tiles) << "frame " << frame << " request " << i;
    ASSERT_EQ(got[i].moved, expected[i].moved) << "frame " << frame << " request " << i;
  }
}

// The pool's passes (which lights keep their tiles, the placements) decide what one thread does,
// through churn that moves, demotes and drops lights.
TEST(ShadowAtlasPlanner, OnAThreadPoolPlansAsSerially) {
  const AtlasConfig config{.page_size = 1024, .max_pages = 2, .min_resolution = 32};
  ShadowAtlasPlanner serial(config);
  ShadowAtlasPlanner pooled(config);
  jobs::ThreadPool threads(3);
  Churn churn(5);
  for (int frame = 0; frame < 60; ++frame) {
    const std::vector<ShadowRequest> requests = churn.next();
    std::vector<Placed> got = plan(pooled, requests, &threads);
    ASSERT_NO_FATAL_FAILURE(expect_same_placements(got, plan(serial, requests), frame));
  }
  EXPECT_GT(serial.stats().demoted_by_budget + serial.stats().dropped_by_budget, 0u);  // over budget
}

// Lights found by their slots (their views' places, as ShadowSchedule gives them) plan as lights
// found by their places among the requests, which lights leaving and entering sight shift every
// frame; on a pool, a light moving to another slot now and then; and with half the slots out of
// the range given, those lights looked up by key.
TEST(ShadowAtlasPlanner, LightsFoundByTheirSlotsPlanAsLightsFoundByKey) {
  const AtlasConfig config{.page_size = 1024, .max_pages = 2, .min_resolution = 32};
  ShadowAtlasPlanner by_place(config);
  ShadowAtlasPlanner by_slot(config);
  ShadowAtlasPlanner by_some_slots(config);
  jobs::ThreadPool threads(3);
  Churn churn(7);
  std::vector<uint32_t> slot_of_key(churn.lights());
  std::iota(slot_of_key.begin(), slot_of_key.end(), 0u);
  for (int frame = 0; frame < 60; ++frame) {
    if (frame % 10 == 9) std::swap(slot_of_key[frame], slot_of_key[frame + 300]);
    const std::vector<ShadowRequest> requests = churn.next(slot_of_key);
    std::vector<Placed> got = plan(by_slot, requests, &threads, 0.0f, churn.lights());
    const std::vector<Placed> expected = plan(by_place, requests);
    ASSERT_NO_FATAL_FAILURE(expect_same_placements(got, expected, frame));
    got = plan(by_some_slots, requests, &threads, 0.0f, churn.lights() / 2);
    ASSERT_NO_FATAL_FAILURE(expect_same_placements(got, expected, frame));
  }
  EXPECT_GT(by_place.stats().demoted_by_budget + by_place.stats().dropped_by_budget, 0u);  // over budget
}

TEST(ShadowAtlasPlanner, ANewBudgetRepacksIntoIt) {
  AtlasConfig config{.page_size = 1024, .max_pages = 4, .min_resolution = 32};
  ShadowAtlasPlanner planner(config);
  std::vector<ShadowRequest> requests;
  for (uint64_t i = 0; i < 8; ++i) requests.push_back(map_light(i, 512.0f + 5.0f * float(i)));
  plan(planner, requests);
  EXPECT_EQ(planner.stats().pages_used, 2u);

  config.max_pages = 1;
  planner.set_config(config);
  const std::vector<Placed> shrunk = plan(planner, requests);
  expect_valid_tiles(config, requests, shrunk);
  EXPECT_EQ(planner.stats().pages_used, 1u);
  EXPECT_EQ(shrunk[7].resolution, 512u);
  EXPECT_EQ(shrunk[0].resolution, 256u);

  config.max_pages = 4;
  planner.set_config(config);
  const std::vector<Placed> grown = plan(planner, requests);
  expect_valid_tiles(config, requests, grown);
  for (const Placed& placement : grown) EXPECT_EQ(placement.resolution, 512u);
}

TEST(ShadowAtlasPlanner, BudgetMessagesAreRateLimitedAndSayWhenShadowsAreRestored) {
  ShadowAtlasPlanner planner({.page_size = 256, .max_pages = 1, .min_resolution = 32});
  std::vector<ShadowRequest> many;
  for (uint64_t i = 0; i < 100; ++i) many.push_back(map_light(i, 32.0f + float(i)));
  EXPECT_FALSE(planner.take_budget_message()) << "nothing planned yet";
  plan(planner, many);
  const std::optional<std::string> first = planner.take_budget_message();
  ASSERT_TRUE(first);
  EXPECT_NE(first->find("36 without shadow"), std::string::npos) << *first;
  EXPECT_FALSE(planner.take_budget_message()) << "nothing changed";

  // The effect changes every frame, but a line comes only once a budget_message_interval.
  int lines = 0;
  for (uint64_t frame = 1; frame < ShadowAtlasPlanner::budget_message_interval; ++frame) {
    many.push_back(map_light(1000 + frame, 1.0f));
    plan(planner, many);
    lines += planner.take_budget_message().has_value();
  }
  EXPECT_EQ(lines, 0);
  plan(planner, {map_light(1, 32.0f)});
  const std::optional<std::string> restored = planner.take_budget_message();
  ASSERT_TRUE(restored);
  EXPECT_NE(restored->find("again"), std::string::npos) << *restored;
}

}  // namespace
}  // namespace sg::shadows
