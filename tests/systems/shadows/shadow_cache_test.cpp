// SPDX-License-Identifier: MIT
// The shadow-map caching policy: which lights re-render their maps, and which maps may be sampled.
#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "ecs/jobs/thread_pool.h"

#include "systems/shadows/caster_changes.h"
#include "systems/shadows/shadow_cache.h"
#include "systems/shadows/spheres_meeting_boxes.h"

namespace sg::shadows {
namespace {

ShadowCacheLight spot(uint64_t key, glm::vec3 centre = glm::vec3(0.0f), float radius = 1.0f) {
  return {key, glm::vec4(centre, radius), false, false, 1};
}

ShadowCacheLight cube(uint64_t key) {
  ShadowCacheLight light = spot(key);
  light.views = 6;
  return light;
}

struct Plan {
  std::vector<uint8_t> render;
  std::vector<uint8_t> usable;
};

Plan plan(ShadowCache& cache, std::span<const ShadowCacheLight> lights, uint32_t view_budget = 0,
          std::span<const scene::Aabb> changed_casters = {}) {
  Plan out{std::vector<uint8_t>(lights.size()), std::vector<uint8_t>(lights.size())};
  cache.plan(lights, {changed_casters, {}}, view_budget, false, out.render, out.usable);
  return out;
}

// A plan where the renderer keeps static layers, with still and moving casters' changes.
Plan plan_layered(ShadowCache& cache, std::span<const ShadowCacheLight> lights,
                  std::span<const scene::Aabb> still = {}, std::span<const scene::Aabb> moving = {}) {
  Plan out{std::vector<uint8_t>(lights.size()), std::vector<uint8_t>(lights.size())};
  cache.plan(lights, {still, moving}, 0, true, out.render, out.usable);
  return out;
}

std::vector<uint8_t> all(size_t count, uint8_t value) { return std::vector<uint8_t>(count, value); }

// A frame's lights with `changed` cleared, as the renderer passes them when nothing happened.
std::vector<ShadowCacheLight> unchanged(std::vector<ShadowCacheLight> lights) {
  for (ShadowCacheLight& light : lights) light.changed = light.invalid = false;
  return lights;
}

TEST(ShadowCache, NewLightsRenderThenStayCachedWhileNothingChanges) {
  ShadowCache cache;
  const std::vector<ShadowCacheLight> lights{spot(1), cube(2), spot(3)};
  Plan first = plan(cache, lights);
  EXPECT_EQ(first.render, all(3, 1));
  EXPECT_EQ(first.usable, all(3, 1));
  EXPECT_EQ(cache.stats().views_rendered, 8u);
  EXPECT_EQ(cache.stats().lights_rendered, 3u);

  for (int frame = 0; frame < 3; ++frame) {
    const Plan next = plan(cache, lights);
    EXPECT_EQ(next.render, all(3, 0));
    EXPECT_EQ(next.usable, all(3, 1));
    EXPECT_EQ(cache.stats().views_rendered, 0u);
    EXPECT_EQ(cache.stats().views_cached, 8u);
    EXPECT_EQ(cache.stats().lights_waiting, 0u);
    EXPECT_EQ(cache.stats().lights_unavailable, 0u);
  }
}

// ShadowSettings::update: every_frame renders unchanged; on_demand ignores caster changes (still
// or moving) and renders when `changed` (asked) or invalid.
TEST(ShadowCache, UpdateModesRenderEveryFrameOrOnlyWhenAsked) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), spot(2), spot(3)};
  lights[1].update = scene::ShadowUpdate::every_frame;
  lights[2].update = scene::ShadowUpdate::on_demand;
  plan(cache, lights);
  const std::vector<ShadowCacheLight> still = unchanged(lights);
  EXPECT_EQ(plan(cache, still).render, (std::vector<uint8_t>{0, 1, 0}));
  const std::vector<scene::Aabb> crate{{glm::vec3(-0.5f), glm::vec3(0.5f)}};  // in every light's reach
  EXPECT_EQ(plan(cache, still, 0, crate).render, (std::vector<uint8_t>{1, 1, 0}));
  EXPECT_EQ(plan_layered(cache, still, {}, crate).render[2], keep_map) << "moving casters too";
  EXPECT_EQ(plan(cache, still).usable[2], 1) << "its old map is sampled";
  std::vector<ShadowCacheLight> asked = still;
  asked[2].changed = true;
  EXPECT_EQ(plan(cache, asked).render, (std::vector<uint8_t>{0, 1, 1}));
  std::vector<ShadowCacheLight> moved_tile = still;
  moved_tile[2].invalid = true;
  EXPECT_EQ(plan(cache, moved_tile).render[2], 1) << "a new tile holds nothing to keep";
}

TEST(ShadowCache, AChangedLightRendersAlone) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), spot(2), spot(3)};
  plan(cache, lights);
  lights[1].changed = true;
  EXPECT_EQ(plan(cache, lights).render, (std::vector<uint8_t>{0, 1, 0}));
  EXPECT_EQ(plan(cache, unchanged(lights)).render, all(3, 0));
}

TEST(ShadowCache, LightsAreKnownByKeyNotByPlace) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), spot(2), spot(3)};
  plan(cache, lights);
  std::reverse(lights.begin(), lights.end());
  EXPECT_EQ(plan(cache, lights).render, all(3, 0));

  // Light 2 gone for a frame, then back: it is new again.
  const std::vector<ShadowCacheLight> without_2{spot(1), spot(3)};
  EXPECT_EQ(plan(cache, without_2).render, all(2, 0));
  const Plan back = plan(cache, lights);
  EXPECT_EQ(back.render, (std::vector<uint8_t>{0, 1, 0}));
}

// A light without storage this frame keeps its place in the list (so the others need no lookup
// by key) but is as if gone: nothing renders or counts it, casters do not reach it, and when it
// is placed again it is new, ahead of stale lights.
TEST(ShadowCache, ALightNotPlacedIsAsIfGoneButKeepsItsPlace) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), cube(2), spot(3)};
  plan(cache, lights);
  lights[1].placed = false;
  const std::vector<scene::Aabb> everywhere{{glm::vec3(-10.0f), glm::vec3(10.0f)}};
  const Plan away = plan(cache, lights, 0, everywhere);
  EXPECT_EQ(away.render, (std::vector<uint8_t>{1, 0, 1}));
  EXPECT_EQ(away.usable, (std::vector<uint8_t>{1, 0, 1}));
  EXPECT_EQ(cache.stats().views_rendered, 2u);
  EXPECT_EQ(cache.stats().views_cached, 0u);
  EXPECT_EQ(cache.stats().lights_unavailable, 0u);
  EXPECT_EQ(cache.stats().lights_due, 2u);

  // Back, with light 1 changed too and a budget for one light: the new one renders first.
  lights[1].placed = true;
  lights[0].changed = true;
  const Plan back = plan(cache, lights, 6);
  EXPECT_EQ(back.render, (std::vector<uint8_t>{0, 1, 0}));
  EXPECT_EQ(back.usable, all(3, 1));
  EXPECT_EQ(cache.stats().lights_waiting, 1u);
}

TEST(ShadowCache, AnInvalidLightIsUnusableUntilRendered) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), spot(2)};
  plan(cache, lights);
  lights[0].invalid = lights[1].invalid = true;  // e.g. both moved to other atlas places
  Plan over_budget = plan(cache, lights, 1);
  EXPECT_EQ(over_budget.render, (std::vector<uint8_t>{1, 0}));  // equally stale: by key
  EXPECT_EQ(over_budget.usable, (std::vector<uint8_t>{1, 0}));
  EXPECT_EQ(cache.stats().lights_unavailable, 1u);
  EXPECT_EQ(cache.stats().lights_waiting, 1u);

  // No longer flagged, but its map was never rendered into its new storage.
  const Plan next = plan(cache, unchanged(lights), 1);
  EXPECT_EQ(next.render, (std::vector<uint8_t>{0, 1}));
  EXPECT_EQ(next.usable, all(2, 1));
}

TEST(ShadowCache, ALightSkippedByTheBudgetStaysDirtyAndSamplesItsStaleMap) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), spot(2), spot(3)};
  plan(cache, lights);
  lights[0].changed = lights[2].changed = true;
  const Plan changed = plan(cache, lights, 1);
  EXPECT_EQ(changed.render, (std::vector<uint8_t>{1, 0, 0}));
  EXPECT_EQ(changed.usable, all(3, 1));
  EXPECT_EQ(cache.stats().lights_waiting, 1u);
  EXPECT_EQ(cache.stats().views_cached, 2u);

  // Nothing happens any more, yet light 3 still owes its render.
  EXPECT_EQ(plan(cache, unchanged(lights), 1).render, (std::vector<uint8_t>{0, 0, 1}));
  EXPECT_EQ(plan(cache, unchanged(lights), 1).render, all(3, 0));
}

TEST(ShadowCache, LightsWithoutAValidMapComeBeforeStaleOnes) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), spot(2)};
  plan(cache, lights);
  lights[1].changed = true;
  plan(cache, lights);  // light 2 is now the fresher of the two
  lights[1].changed = false;

  lights[0].changed = true;
  lights[1].invalid = true;
  EXPECT_EQ(plan(cache, lights, 1).render, (std::vector<uint8_t>{0, 1}));

  // A new light, too, comes before the stale one.
  lights = unchanged(lights);
  lights.push_back(spot(0));
  EXPECT_EQ(plan(cache, lights, 1).render, (std::vector<uint8_t>{0, 0, 1}));
  EXPECT_EQ(plan(cache, lights, 1).render, (std::vector<uint8_t>{1, 0, 0}));
}

// With keys as the only order, light 9 would never render while the others keep changing.
TEST(ShadowCache, NoLightStarvesWhenTheBudgetIsShort) {
  constexpr uint32_t light_count = 10;
  constexpr uint32_t budget = 3;
  constexpr int frames_per_round = (light_count + budget - 1) / budget;
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights;
  for (uint32_t key = 0; key < light_count; ++key) lights.push_back(spot(key));
  std::vector<int> last_rendered(light_count, 0);
  for (int frame = 1; frame <= 40; ++frame) {
    const Plan p = plan(cache, lights, budget);
    EXPECT_EQ(cache.stats().views_rendered, budget);
    for (uint32_t i = 0; i < light_count; ++i) {
      if (p.render[i] != 0) last_rendered[i] = frame;
      EXPECT_LE(frame - last_rendered[i], frames_per_round - 1) << "light " << i << " frame " << frame;
    }
    for (ShadowCacheLight& light : lights) light.changed = true;  // every light changes every frame
  }
}

// How far maps lag: four lights changing every frame, one rendered a frame, round the lights in
// turn. In steady state the lights due are all four, a frame after each is rendered its map has
// been wrong one frame, then two, then three, then it renders (0): lags {0, 1, 2, 3}. A still
// light is never due; with no budget every due light renders and nothing lags.
TEST(ShadowCache, LagCountsTheFramesEachDueMapHasBeenWrong) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), spot(2), spot(3), spot(4), spot(5)};
  plan(cache, lights, 0);  // all new: every one renders
  EXPECT_EQ(cache.stats().lights_due, 5u);
  EXPECT_EQ(cache.stats().lag_max, 0u);
  for (int frame = 0; frame < 12; ++frame) {
    for (size_t i = 0; i < 4; ++i) lights[i].changed = true;  // light 5 stays still
    plan(cache, lights, 1);
    const ShadowCacheStats& stats = cache.stats();
    EXPECT_EQ(stats.lights_due, 4u) << "frame " << frame;
    if (frame >= 4) {
      EXPECT_EQ(stats.lag_p50, 1u) << "frame " << frame;
      EXPECT_EQ(stats.lag_p99, 2u) << "frame " << frame;
      EXPECT_EQ(stats.lag_max, 3u) << "frame " << frame;
    }
  }
  for (size_t i = 0; i < 4; ++i) lights[i].changed = true;
  plan(cache, lights, 0);
  EXPECT_EQ(cache.stats().lights_due, 4u);
  EXPECT_EQ(cache.stats().lag_max, 0u) << "every due map rendered";
  for (ShadowCacheLight& light : lights) light.changed = false;
  plan(cache, lights, 1);
  EXPECT_EQ(cache.stats().lights_due, 0u);
  EXPECT_EQ(cache.stats().lag_p50, 0u);
}

// Lags past a thousand frames are ranked as exactly as short ones: 2,000 lights changing every
// frame under a budget of one view render in turn, and once each has rendered the due lights lag
// 0, 1, ..., 1999 frames (the one rendered this frame 0).
TEST(ShadowCache, LongLagsAreRankedExactly) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights;
  for (uint64_t key = 1; key <= 2000; ++key) lights.push_back(spot(key));
  for (int frame = 0; frame < 2100; ++frame) {
    for (ShadowCacheLight& light : lights) light.changed = true;
    plan(cache, lights, 1);
  }
  const ShadowCacheStats& stats = cache.stats();
  EXPECT_EQ(stats.lights_due, 2000u);
  EXPECT_EQ(stats.lag_p50, 999u);   // rank 999 of 0..1999
  EXPECT_EQ(stats.lag_p99, 1979u);  // rank floor(0.99 * 1999)
  EXPECT_EQ(stats.lag_max, 1999u);
}

// Thousands of dirty lights over the view budget, their staleness spread by random changes and
// invalidations:
// the choice is, frame after frame, a plain model's: lights without a valid map, then the
// others, each by the frame they last rendered in, ties by key, each taken while its views fit (cubes leave
// views no cube fits, so lights behind them are looked at too); on a pool as on one thread.
// Spots and cubes; with `sizes`, lights of two and three views too, so that the views a cube
// leaves are taken by lights that do not all fit.
TEST(ShadowCache, ChoosesTheStalestInOrderAsAPlainModelDoes) {
  for (const auto& [light_count, sizes] :
       {std::pair(1500u, false), std::pair(3000u, false), std::pair(3000u, true)}) {
    std::vector<ShadowCacheLight> lights;
    std::mt19937 random(light_count + sizes);
    for (uint32_t i = 0; i < light_count; ++i) {
      const uint64_t key = uint64_t{random()} << 16 | i;  // keys out of order
      lights.push_back(i % 3 == 0 ? spot(key) : cube(key));
      if (sizes && i % 3 == 1) lights.back().views = 2 + i % 2;
    }
    const uint32_t budget = light_count + 3;
    ShadowCache serial;
    ShadowCache pooled;
    jobs::ThreadPool threads(3);
    struct Model {
      bool dirty = true;
      bool valid = false;
      int rendered = 0;
    };
    std::vector<Model> model(light_count);
    for (int frame = 1; frame <= 12; ++frame) {
      std::vector<uint32_t> order;
      for (uint32_t i = 0; i < light_count; ++i) {
        if (lights[i].invalid) model[i].valid = false;
        model[i].dirty = model[i].dirty || lights[i].changed || !model[i].valid;
        if (model[i].dirty) order.push_back(i);
      }
      const auto rank = [&](uint32_t i) { return (model[i].valid ? 1000 : 0) + model[i].rendered; };
      std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return rank(a) < rank(b) || (rank(a) == rank(b) && lights[a].key < lights[b].key);
      });
      std::vector<uint8_t> expected(light_count, 0);
      uint32_t left = budget;
      for (const uint32_t i : order) {
        if (lights[i].views > left) continue;  // something rendered already: the budget is large
        expected[i] = 1;
        left -= lights[i].views;
        model[i] = {false, true, frame};
      }

      EXPECT_EQ(plan(serial, lights, budget).render, expected) << light_count << " lights, frame " << frame;
      Plan got{std::vector<uint8_t>(lights.size()), std::vector<uint8_t>(lights.size())};
      pooled.plan(lights, {}, budget, false, got.render, got.usable, &threads);
      ASSERT_EQ(got.render, expected) << light_count << " lights, frame " << frame;
      for (ShadowCacheLight& light : lights) {
        light.changed = random() % 2 == 0;
        light.invalid = random() % 8 == 0;  // moved in the atlas: rendered before, no valid map now
      }
    }
  }
}

TEST(ShadowCache, EveryDirtyLightRendersWithinTotalOverBudgetFrames) {
  constexpr uint32_t light_count = 10;
  constexpr uint32_t budget = 4;
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights;
  for (uint32_t key = 0; key < light_count; ++key) lights.push_back(spot(key * 7 % light_count));
  std::vector<uint8_t> rendered(light_count, 0);
  for (uint32_t frame = 0; frame < (light_count + budget - 1) / budget; ++frame) {
    const Plan p = plan(cache, lights, budget);
    for (uint32_t i = 0; i < light_count; ++i) rendered[i] |= p.render[i];
  }
  EXPECT_EQ(rendered, all(light_count, 1));
  EXPECT_EQ(cache.stats().lights_waiting, 0u);
  EXPECT_EQ(plan(cache, lights, budget).render, all(light_count, 0));
}

TEST(ShadowCache, ABudgetUnderSixViewsStillRendersCubesOneAFrame) {
  ShadowCache cache;
  const std::vector<ShadowCacheLight> cubes{cube(1), cube(2), cube(3)};
  for (int frame = 0; frame < 3; ++frame) {
    plan(cache, cubes, 4);
    EXPECT_EQ(cache.stats().lights_rendered, 1u);
    EXPECT_EQ(cache.stats().views_rendered, 6u);
  }
  EXPECT_EQ(cache.stats().lights_waiting, 0u);
  EXPECT_EQ(cache.stats().lights_unavailable, 0u);
}

TEST(ShadowCache, ALightLargerThanTheBudgetLeftWaitsWhileSmallerOnesBehindItRender) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), cube(2), spot(3)};
  const Plan first = plan(cache, lights, 6);
  EXPECT_EQ(first.render, (std::vector<uint8_t>{1, 0, 1}));
  EXPECT_EQ(first.usable, (std::vector<uint8_t>{1, 0, 1}));
  EXPECT_EQ(cache.stats().views_rendered, 2u);

  // The cube, still without a map, now comes first and takes the whole budget.
  lights[0].changed = lights[2].changed = true;
  const Plan second = plan(cache, lights, 6);
  EXPECT_EQ(second.render, (std::vector<uint8_t>{0, 1, 0}));
  EXPECT_EQ(cache.stats().lights_waiting, 2u);
}

// The views a skipped cube leaves go to the stalest later lights that fit, in key order within a
// staleness, each as the views left allow: lights of two and three views here, so that one is
// skipped there too.
TEST(ShadowCache, ViewsACubeLeftGoToTheStalestLaterLightsThatFit) {
  ShadowCache cache;
  std::vector<ShadowCacheLight> lights{spot(1), cube(2), spot(10), spot(11), spot(12), spot(13)};
  lights[2].views = 3;
  lights[3].views = 2;
  plan(cache, lights);  // every map drawn on frame 1
  for (size_t i = 2; i < lights.size(); ++i) lights[i].changed = true;
  plan(cache, lights);  // the later four again on frame 2: staler are the first two
  for (ShadowCacheLight& light : lights) light.changed = true;
  // Five views: the spot keyed 1 takes one, the cube does not fit the four left; of them the
  // three-view light takes three, the two-view one does not fit what is left, the spot keyed 12
  // takes it.
  EXPECT_EQ(plan(cache, lights, 5).render, (std::vector<uint8_t>{1, 0, 1, 0, 1, 0}));
  EXPECT_EQ(cache.stats().views_rendered, 5u);
}

TEST(ShadowCache, InvalidateAllMakesEveryMapUnusableUntilRendered) {
  ShadowCache cache;
  const std::vector<ShadowCacheLight> lights{spot(1), spot(2), spot(3)};
  plan(cache, lights);
  cache.invalidate_all();
  const Plan p = plan(cache, lights, 2);
  EXPECT_EQ(p.render, (std::vector<uint8_t>{1, 1, 0}));
  EXPECT_EQ(p.usable, (std::vector<uint8_t>{1, 1, 0}));
  EXPECT_EQ(cache.stats().lights_unavailable, 1u);
  EXPECT_EQ(plan(cache, lights, 2).render, (std::vector<uint8_t>{0, 0, 1}));
}

TEST(ShadowCache, RenderAndUsableNeedOneElementPerLight) {
  ShadowCache cache;
  const std::vector<ShadowCacheLight> lights{spot(1), spot(2)};
  std::vector<uint8_t> render(2);
  std::vector<uint8_t> usable(1);
  EXPECT_THROW(cache.plan(lights, {}, 0, false, render, usable), std::invalid_argument);
}

// Static layers: a map that only moving casters made wrong redraws just those over its layer,
// once it has one that still matches; anything else draws every caster again.
TEST(ShadowCache, MovingCastersAloneRedrawOverTheStaticLayer) {
  ShadowCache cache;
  ShadowCacheLight a = spot(1);
  a.reach = {0.0f, 0.0f, 0.0f, 2.0f};
  ShadowCacheLight b = spot(2);
  b.reach = {10.0f, 0.0f, 0.0f, 2.0f};
  std::vector<ShadowCacheLight> lights{a, b};
  const std::vector<scene::Aabb> near_a{{glm::vec3(1.0f), glm::vec3(1.5f)}};
  EXPECT_EQ(plan_layered(cache, lights).render, all(2, draw_all_casters)) << "new maps";
  lights = unchanged(lights);
  EXPECT_EQ(plan_layered(cache, lights, {}, near_a).render,
            (std::vector<uint8_t>{draw_moving_casters, keep_map}));
  EXPECT_EQ(cache.stats().views_moving_only, 1u);
  EXPECT_EQ(plan_layered(cache, lights, near_a, near_a).render,
            (std::vector<uint8_t>{draw_all_casters, keep_map}))
      << "a still caster changed there too";
  lights[0].changed = true;
  EXPECT_EQ(plan_layered(cache, lights, {}, near_a).render,
            (std::vector<uint8_t>{draw_all_casters, keep_map}))
      << "the light moved";
  lights = unchanged(lights);
  lights[0].invalid = true;
  EXPECT_EQ(plan_layered(cache, lights, {}, near_a).render,
            (std::vector<uint8_t>{draw_all_casters, keep_map}))
      << "its tile moved";
  lights = unchanged(lights);
  EXPECT_EQ(plan_layered(cache, lights, {}, near_a).render,
            (std::vector<uint8_t>{draw_moving_casters, keep_map}));

  // Layers forgotten, or not kept by the frame's path: every caster once, then moving ones again.
  cache.forget_static_layers();
  EXPECT_EQ(plan_layered(cache, lights, {}, near_a).render,
            (std::vector<uint8_t>{draw_all_casters, keep_map}));
  cache.static_layers_not_kept();
  EXPECT_EQ(plan_layered(cache, lights, {}, near_a).render,
            (std::vector<uint8_t>{draw_all_casters, keep_map}));
  EXPECT_EQ(plan_layered(cache, lights, {}, near_a).render,
            (std::vector<uint8_t>{draw_moving_casters, keep_map}));
  cache.static_layers_not_kept();  // no render with every caster in that plan: nothing lost
  EXPECT_EQ(plan_layered(cache, lights, {}, near_a).render,
            (std::vector<uint8_t>{draw_moving_casters, keep_map}));

  // Without static layers every render draws every caster.
  Plan plain{std::vector<uint8_t>(2), std::vector<uint8_t>(2)};
  cache.plan(lights, {{}, near_a}, 0, false, plain.render, plain.usable);
  EXPECT_EQ(plain.render, (std::vector<uint8_t>{draw_all_casters, keep_map}));
  cache.invalidate_all();
  EXPECT_EQ(plan_layered(cache, lights, {}, near_a).render, all(2, draw_all_casters));
}

// Lights 10 apart on a 10 x 10 grid in x-z, 5 above the floor, reaching 6: light (i, j) has key
// 10 * i + j. Caster boxes sit on the floor.
std::vector<ShadowCacheLight> light_grid() {
  std::vector<ShadowCacheLight> lights;
  for (uint64_t i = 0; i < 10; ++i) {
    for (uint64_t j = 0; j < 10; ++j)
      lights.push_back(spot(10 * i + j, glm::vec3(10.0f * i, 5.0f, 10.0f * j), 6.0f));
  }
  return lights;
}

CasterBounds caster_at(uint64_t key, float x, float z) {
  return {key, {glm::vec3(x - 1.0f, 0.0f, z - 1.0f), glm::vec3(x + 1.0f, 2.0f, z + 1.0f)}};
}

std::vector<uint64_t> rendered_keys(std::span<const ShadowCacheLight> lights, const Plan& p) {
  std::vector<uint64_t> keys;
  for (size_t i = 0; i < lights.size(); ++i) {
    if (p.render[i] != 0) keys.push_back(lights[i].key);
  }
  return keys;
}

TEST(ShadowCache, AMovedCasterRendersExactlyTheLightsWhoseReachItLeftOrEntered) {
  ShadowCache cache;
  CasterChangeTracker tracker;
  std::vector<ShadowCacheLight> lights = light_grid();
  std::vector<CasterBounds> casters{caster_at(0, 20.0f, 30.0f), caster_at(1, 70.0f, 70.0f)};
  plan(cache, lights, 0, tracker.update(casters));

  // Under light (2, 3) only, it moves to between lights (2, 3) and (3, 3).
  casters[0] = caster_at(0, 25.0f, 30.0f);
  std::span<const scene::Aabb> changes = tracker.update(casters);
  const Plan moved = plan(cache, lights, 0, changes);
  EXPECT_EQ(rendered_keys(lights, moved), (std::vector<uint64_t>{23, 33}));
  for (size_t i = 0; i < lights.size(); ++i) {
    const bool reached = std::any_of(changes.begin(), changes.end(), [&](const scene::Aabb& box) {
      return sphere_meets_box(lights[i].reach, box);
    });
    EXPECT_EQ(moved.render[i] != 0, reached) << "light " << lights[i].key;
  }

  // It moves on to under light (5, 5): the lights it left render too.
  casters[0] = caster_at(0, 50.0f, 50.0f);
  EXPECT_EQ(rendered_keys(lights, plan(cache, lights, 0, tracker.update(casters))),
            (std::vector<uint64_t>{23, 33, 55}));

  // Nothing moves: nothing renders.
  const Plan still = plan(cache, lights, 0, tracker.update(casters));
  EXPECT_EQ(still.render, all(lights.size(), 0));
  EXPECT_EQ(still.usable, all(lights.size(), 1));
}

TEST(ShadowCache, AnUnboundedLightRendersOnAnyCasterChangeOnly) {
  ShadowCache cache;
  CasterChangeTracker tracker;
  std::vector<ShadowCacheLight> lights = light_grid();
  lights.push_back({1'000, glm::vec4(0.0f, 0.0f, 0.0f, -1.0f), false, false, 1});  // e.g. the sun
  std::vector<CasterBounds> casters{caster_at(0, 500.0f, 500.0f)};  // far from every bounded light
  plan(cache, lights, 0, tracker.update(casters));

  EXPECT_TRUE(rendered_keys(lights, plan(cache, lights, 0, tracker.update(casters))).empty());
  casters[0] = caster_at(0, 510.0f, 500.0f);
  EXPECT_EQ(rendered_keys(lights, plan(cache, lights, 0, tracker.update(casters))),
            (std::vector<uint64_t>{1'000}));
}

// Many lights, many boxes, some lights dirty already and some unbounded: the cache renders
// exactly the lights a test of every light against every box finds.
TEST(ShadowCache, ManyChangedCastersRenderExactlyTheLightsTheyReach) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> coordinate(-500.0f, 500.0f);
  std::uniform_real_distribution<float> radius(0.5f, 15.0f);
  std::vector<ShadowCacheLight> lights;
  for (uint64_t key = 0; key < 20'000; ++key) {
    lights.push_back(spot(key, glm::vec3(coordinate(random), 0.0f, coordinate(random)), radius(random)));
    if (key % 1'000 == 0) lights.back().reach.w = -1.0f;
  }
  std::vector<scene::Aabb> boxes;
  for (int b = 0; b < 300; ++b) {
    const glm::vec3 min(coordinate(random), -1.0f, coordinate(random));
    boxes.push_back({min, min + glm::vec3(3.0f)});
  }

  ShadowCache cache;
  plan(cache, lights);
  for (size_t i = 0; i < lights.size(); i += 7) lights[i].changed = true;
  const Plan p = plan(cache, lights, 0, boxes);
  size_t rendered = 0;
  for (size_t i = 0; i < lights.size(); ++i) {
    const bool reached = lights[i].reach.w < 0.0f || std::any_of(boxes.begin(), boxes.end(), [&](auto& box) {
                           return sphere_meets_box(lights[i].reach, box);
                         });
    ASSERT_EQ(p.render[i] != 0, reached || lights[i].changed) << "light " << i;
    rendered += p.render[i];
  }
  EXPECT_LT(rendered, lights.size() / 2);  // the test means something: most lights stay cached
}

// The passes over the lights run in pieces on a pool: frames of changed, invalid, unplaced lights,
// still and moving casters and a short budget plan there as on one thread, counts and lags included.
TEST(ShadowCache, OnAPoolPlansAsOnOneThread) {
  std::mt19937 random(5);
  std::uniform_real_distribution<float> coordinate(-200.0f, 200.0f);
  std::vector<ShadowCacheLight> lights;
  for (uint64_t key = 0; key < 5'000; ++key) {
    lights.push_back(key % 4 == 0 ? cube(key) : spot(key));
    lights.back().reach =
        glm::vec4(coordinate(random), 0.0f, coordinate(random), key % 500 == 0 ? -1.0f : 8.0f);
  }
  ShadowCache serial;
  ShadowCache pooled;
  jobs::ThreadPool threads(3);
  for (int frame = 0; frame < 10; ++frame) {
    std::vector<scene::Aabb> still;
    std::vector<scene::Aabb> moving;
    for (int b = 0; b < 20; ++b) {
      const glm::vec3 min(coordinate(random), -1.0f, coordinate(random));
      (b % 2 == 0 ? still : moving).push_back({min, min + glm::vec3(4.0f)});
    }
    Plan one{all(lights.size(), 0), all(lights.size(), 0)};
    Plan many = one;
    serial.plan(lights, {still, moving}, 900, true, one.render, one.usable);
    pooled.plan(lights, {still, moving}, 900, true, many.render, many.usable, &threads);
    ASSERT_EQ(many.render, one.render) << "frame " << frame;
    ASSERT_EQ(many.usable, one.usable) << "frame " << frame;
    EXPECT_TRUE(pooled.stats() == serial.stats()) << "frame " << frame;
    EXPECT_GT(serial.stats().lights_waiting, 0u);  // the budget was short
    for (ShadowCacheLight& light : lights) {
      light.changed = random() % 20 == 0;
      light.invalid = random() % 50 == 0;
      light.placed = random() % 30 != 0;
    }
  }
}

// Equally stale dirty lights render in key order whether they are few (sorted on their own) or
// many (read from every light's key order).
TEST(ShadowCache, FewOrManyDirtyLightsRenderInKeyOrder) {
  for (const uint64_t dirty_count : {3u, 50u}) {
    std::vector<ShadowCacheLight> lights;
    for (uint64_t i = 0; i < 100; ++i) lights.push_back(spot((i * 37) % 100 + 1));  // keys out of order
    ShadowCache cache;
    plan(cache, lights);
    std::vector<uint64_t> dirty_keys;
    for (uint64_t i = 0; i < dirty_count; ++i) {
      lights[i * 2].changed = true;
      dirty_keys.push_back(lights[i * 2].key);
    }
    std::sort(dirty_keys.begin(), dirty_keys.end());
    for (const uint64_t key : dirty_keys) {
      EXPECT_EQ(rendered_keys(lights, plan(cache, lights, 1)), (std::vector<uint64_t>{key})) << dirty_count;
      lights = unchanged(lights);
    }
    EXPECT_TRUE(rendered_keys(lights, plan(cache, lights, 1)).empty());
  }
}

// Renders thousands of frames apart put several ranks of staleness in one bucket of the budget's
// histogram: the bucket where the budget runs out is still ordered by staleness, then key.
TEST(ShadowCache, ChoosesTheStalestWhenRendersLieThousandsOfFramesApart) {
  // Keys against staleness: light i is rendered last at frame i + 1, light 4 thousands later.
  std::vector<ShadowCacheLight> lights{spot(50), spot(40), spot(30), spot(20), spot(10)};
  ShadowCache cache;
  for (size_t i = 0; i < 4; ++i) {
    std::vector<ShadowCacheLight> frame = unchanged(lights);
    frame[i].changed = true;
    plan(cache, frame, i == 0 ? 0 : 1);  // the first frame renders every new light
  }
  for (int frame = 0; frame < 5000; ++frame) {
    std::vector<ShadowCacheLight> moved = unchanged(lights);
    moved[4].changed = true;
    plan(cache, moved, 1);
  }
  std::vector<ShadowCacheLight> all_changed = lights;
  for (ShadowCacheLight& light : all_changed) light.changed = true;
  const std::vector<ShadowCacheLight> none_changed = unchanged(lights);
  std::vector<uint64_t> order;
  for (size_t frame = 0; frame < lights.size(); ++frame) {
    const std::vector<uint64_t> rendered =
        rendered_keys(lights, plan(cache, frame == 0 ? all_changed : none_changed, 1));
    order.insert(order.end(), rendered.begin(), rendered.end());
  }
  EXPECT_EQ(order, (std::vector<uint64_t>{50, 40, 30, 20, 10}));
}

}  // namespace
}  // namespace sg::shadows
