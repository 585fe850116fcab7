// SPDX-License-Identifier: MIT
// Gathering a frame's lights from the ECS world and scheduling their maps, without a GPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include "ecs/jobs/thread_pool.h"
#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene_builder.h"

#include "systems/scene/shadow_requests.h"
#include "systems/shadows/frame_lights.h"
#include "systems/shadows/quality_floor.h"
#include "systems/shadows/shadow_schedule.h"

namespace sg::shadows {
namespace {

// One map per light: the sun's cascades have tests of their own (cascades_test.cpp).
scene::ShadowSettings shadow_at(uint32_t resolution, bool casts = true) {
  scene::ShadowSettings shadow;
  shadow.resolution = resolution;
  shadow.casts_shadow = casts;
  shadow.cascades = 1;
  return shadow;
}

const ecs::LocalTransform above{glm::vec3(0.0f, 5.0f, 0.0f)};
const scene::Aabb bounds{glm::vec3(-10.0f), glm::vec3(10.0f)};

// Two spot lights (one without a shadow), a directional light and two point lights.
scene::Scene five_lights() {
  scene::Scene scene;
  scene::add_light(scene, scene::SpotLight{}, above, shadow_at(512), "key");
  scene::add_light(scene, scene::SpotLight{}, above, shadow_at(512, false), "fill");
  scene::add_light(scene, scene::DirectionalLight{}, above, shadow_at(100'000), "");
  scene::add_light(scene, scene::PointLight{}, above, shadow_at(3), "bulb");
  scene::add_light(scene, scene::PointLight{}, above, shadow_at(256), "lamp");
  ecs::update_world_transforms(scene.world, 0);
  return scene;
}

// sort_by_group into an array of its own (the renderer's is the frame's light buffer).
std::vector<GpuLight> sorted_by_group(FrameLights& lights, jobs::ThreadPool* pool = nullptr) {
  std::vector<GpuLight> sorted(lights.records.size());
  sort_by_group(lights, sorted, pool);
  return sorted;
}

// A camera at `eye` looking down -Z with a 90 degree field of view, 1000 pixels high.
// `record` with `other`'s shadow fields (its map, where and how drawn): what gathering sets, with
// what the schedule sets taken from another record.
GpuLight with_shadow_fields_of(GpuLight record, const GpuLight& other) {
  record.info.w = other.info.w;
  record.shadow_rect = other.shadow_rect;
  record.shadow_depth = other.shadow_depth;
  record.shadow_matrix = other.shadow_matrix;
  return record;
}

ShadowCamera camera_at(glm::vec3 eye) {
  const glm::mat4 view = glm::lookAtRH(eye, eye + glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  const glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, 0.1f, 1000.0f);
  return {eye, projection * view, 1000.0f / glm::radians(90.0f)};
}

constexpr AtlasConfig small_atlas{1024, 4, min_shadow_resolution};

TEST(FrameLights, EveryLightGetsARecordAndShadowCastersGetViews) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);  // a const World is enough

  EXPECT_EQ(lights.records.size(), 5u);
  ASSERT_EQ(lights.maps.size(), 2u);  // "fill" casts none
  ASSERT_EQ(lights.cubes.size(), 2u);
  EXPECT_EQ(lights.maps[0].name, "shadow key");
  EXPECT_EQ(lights.maps[1].name, "shadow directional 1");  // unnamed: kind and map index
  EXPECT_NE(lights.maps[0].key, lights.maps[1].key);
  EXPECT_NE(lights.cubes[0].key, lights.cubes[1].key);
  // Each view points at its own record, of its own type.
  EXPECT_EQ(lights.records[lights.maps[1].light].info.x, uint32_t(GpuLightType::directional));
  EXPECT_EQ(lights.records[lights.cubes[0].light].info.x, uint32_t(GpuLightType::point));
  // Views carry the reach casters are culled against: the spot's sphere, none for the sun.
  EXPECT_GT(lights.maps[0].reach.w, 0.0f);
  EXPECT_LT(lights.maps[1].reach.w, 0.0f);
  // Until scheduled, no record has a map.
  for (const GpuLight& record : lights.records) EXPECT_EQ(record.info.w, no_shadow_map);
}

// A sun's cascades are views of one light: per-light figures (shadowgraph-algorithm-costs) divide
// by the lights.
TEST(FrameLights, CountsACascadedSunAsOneShadowedLight) {
  scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  EXPECT_EQ(shadowed_light_count(lights), 4u);  // "fill" casts none

  scene::ShadowSettings cascaded = shadow_at(1024);
  cascaded.cascades = 3;
  scene::add_light(scene, scene::DirectionalLight{}, above, cascaded, "sun");
  ecs::update_world_transforms(scene.world, 0);
  gather_lights(scene.world, bounds, {}, lights);
  ASSERT_EQ(lights.maps.size(), 5u);  // the key spot, the single-map sun, the sun's three cascades
  EXPECT_EQ(shadowed_light_count(lights), 5u);
}

// Gathering on a thread pool splits the lights into chunks; the result must not depend on it.
TEST(FrameLights, AThreadPoolGathersTheSameLights) {
  scene::Scene scene;
  for (int i = 0; i < 700; ++i) {  // several chunks, every kind, some without a shadow
    const ecs::LocalTransform at{glm::vec3(float(i % 40), 3.0f, float(i / 40))};
    const scene::ShadowSettings shadow = shadow_at(64u << (i % 4), i % 7 != 0);
    if (i % 3 == 0) scene::add_light(scene, scene::PointLight{}, at, shadow, i % 2 ? "p" : "");
    if (i % 3 == 1) scene::add_light(scene, scene::SpotLight{}, at, shadow, "");
    if (i % 3 == 2) scene::add_light(scene, scene::CylinderLight{}, at, shadow, "c");
  }
  ecs::update_world_transforms(scene.world, 0);
  FrameLights serial;
  FrameLights pooled;
  jobs::ThreadPool pool(3);
  gather_lights(scene.world, bounds, {}, serial);
  gather_lights(scene.world, bounds, {}, pooled, &pool);

  ASSERT_EQ(pooled.records.size(), 700u);
  ASSERT_EQ(pooled.maps.size(), serial.maps.size());
  ASSERT_EQ(pooled.cubes.size(), serial.cubes.size());
  EXPECT_EQ(std::memcmp(pooled.records.data(), serial.records.data(), 700 * sizeof(GpuLight)), 0);
  for (size_t m = 0; m < serial.maps.size(); ++m) {
    EXPECT_EQ(pooled.maps[m].light, serial.maps[m].light);
    EXPECT_EQ(pooled.maps[m].key, serial.maps[m].key);
    EXPECT_EQ(pooled.maps[m].name, serial.maps[m].name);
    EXPECT_EQ(pooled.maps[m].view.view_projection(), serial.maps[m].view.view_projection());
  }
  for (size_t c = 0; c < serial.cubes.size(); ++c) {
    EXPECT_EQ(pooled.cubes[c].light, serial.cubes[c].light);
    EXPECT_EQ(pooled.cubes[c].name, serial.cubes[c].name);
    EXPECT_EQ(pooled.cubes[c].position_far, serial.cubes[c].position_far);
  }
}

TEST(FrameLights, RequestedResolutionsAreClamped) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  EXPECT_EQ(lights.maps[0].requested_resolution, 512u);
  EXPECT_EQ(lights.maps[1].requested_resolution, max_map_resolution);
  EXPECT_EQ(lights.cubes[0].requested_resolution, min_shadow_resolution);
  EXPECT_EQ(lights.cubes[1].requested_resolution, 256u);
}

TEST(FrameLights, ShadowsOffLeavesEveryLightWithoutAMap) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  EXPECT_FALSE(lights.maps.empty());
  gather_lights(scene.world, bounds, {false}, lights);  // reuses the storage
  EXPECT_EQ(lights.records.size(), 5u);
  EXPECT_TRUE(lights.maps.empty());
  EXPECT_TRUE(lights.cubes.empty());
}

TEST(FrameLights, ChangedFollowsTheEcsChangeTicks) {
  scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  EXPECT_TRUE(lights.maps[0].changed);  // everything is new to the first gather
  // Writes in the tick of a gather count for the next one too (they may have come after it), so
  // the lights, created in the first gather's tick, are quiet from the third on.
  scene.world.advance_tick();
  gather_lights(scene.world, bounds, {}, lights);
  scene.world.advance_tick();
  gather_lights(scene.world, bounds, {}, lights);
  EXPECT_FALSE(lights.maps[0].changed);
  EXPECT_FALSE(lights.cubes[1].changed);

  scene.world.advance_tick();
  scene.world.query<scene::PointLight>().for_each([](ecs::Entity, scene::PointLight& light) {
    light.range *= 2.0f;  // a written component counts, whatever it holds
  });
  gather_lights(scene.world, bounds, {}, lights);
  EXPECT_FALSE(lights.maps[0].changed);
  EXPECT_TRUE(lights.cubes[0].changed);
  EXPECT_TRUE(lights.cubes[1].changed);
}

// An on_demand light's map is changed only by a request (or a write of its shadow settings), not
// by its own moves; it carries its update mode and priority to the schedule.
TEST(FrameLights, AnOnDemandLightChangesOnlyWhenAsked) {
  scene::Scene scene = five_lights();
  scene.world.query<scene::ShadowSettings>().for_each([](ecs::Entity, scene::ShadowSettings& shadow) {
    shadow.update = scene::ShadowUpdate::on_demand;
    shadow.priority = 1.5f;
  });
  FrameLights lights;
  for (int i = 0; i < 3; ++i) {
    scene.world.advance_tick();
    gather_lights(scene.world, bounds, {}, lights);
  }
  ASSERT_FALSE(lights.cubes[0].changed);
  EXPECT_EQ(lights.cubes[0].update, scene::ShadowUpdate::on_demand);
  EXPECT_EQ(lights.maps[0].priority, 1.5f);

  scene.world.advance_tick();
  ecs::Entity moved = ecs::null_entity;
  scene.world.query<scene::PointLight, ecs::WorldTransform>().for_each(
      [&](ecs::Entity entity, scene::PointLight& light, ecs::WorldTransform& world) {
        light.range *= 2.0f;
        world.matrix[3].x += 1.0f;
        moved = entity;
      });
  gather_lights(scene.world, bounds, {}, lights);
  EXPECT_FALSE(lights.cubes[0].changed) << "moved, not asked";
  EXPECT_FALSE(lights.cubes[1].changed);

  scene.world.advance_tick();
  ASSERT_TRUE(scene::request_shadow_redraw(scene.world, moved));
  gather_lights(scene.world, bounds, {}, lights);
  for (const ShadowCubeView& cube : lights.cubes) {
    EXPECT_EQ(cube.changed, cube.key == light_key(moved)) << "only the light asked";
  }
}

// ShadowSettings::priority: tiers added to log2 of the atlas importance.
TEST(ShadowSchedule, PriorityScalesALightsImportanceByPowersOfTwo) {
  scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  ShadowSchedule schedule(small_atlas);
  const ShadowCamera camera = camera_at({0.0f, 30.0f, 40.0f});
  schedule.schedule(lights, camera, {}, 0);
  const float plain = lights.cubes[0].importance;
  ASSERT_GT(plain, 0.0f);
  lights.cubes[0].priority = 2.0f;
  schedule.schedule(lights, camera, {}, 0);
  EXPECT_FLOAT_EQ(lights.cubes[0].importance, 4.0f * plain);
  lights.cubes[0].priority = -9.0f;  // beyond the range: its end
  schedule.schedule(lights, camera, {}, 0);
  EXPECT_FLOAT_EQ(lights.cubes[0].importance, plain / 16.0f);
}

TEST(ShadowSchedule, GivesEachShadowedRecordItsTiles) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  ShadowSchedule schedule(small_atlas);
  schedule.schedule(lights, camera_at({0.0f, 5.0f, 2.0f}), {}, 0);  // the camera is inside every reach
  sorted_by_group(lights);

  const ShadowMapView& key = lights.maps[0];
  ASSERT_EQ(key.resolution, 512u);
  EXPECT_TRUE(key.render);
  const GpuLight& record = lights.records[key.light];
  EXPECT_EQ(record.info.w, key.tile.page);
  EXPECT_FLOAT_EQ(record.shadow_rect.x, float(key.tile.x) / 1024.0f);
  EXPECT_FLOAT_EQ(record.shadow_rect.z, 512.0f / 1024.0f);  // its 512 texels of a 1024 page
  EXPECT_FLOAT_EQ(record.shadow_depth.z, 1.0f / 512.0f);
  for (const ShadowCubeView& cube : lights.cubes) {
    ASSERT_GT(cube.resolution, 0u);
    const GpuLight& point = lights.records[cube.light];
    for (int f = 0; f < 6; ++f) {
      EXPECT_EQ(cube.tiles[f].page, point.info.w);
      EXPECT_FLOAT_EQ(point.shadow_matrix[f / 2][2 * (f % 2)], float(cube.tiles[f].x) / 1024.0f);
    }
  }
  EXPECT_EQ(schedule.stats().views_rendered, 2u + 12u);
  EXPECT_EQ(schedule.stats().lights_without_shadow, 0u);
}

// Every step of a schedule() is timed, once: the steps add up to no more than the call took.
TEST(ShadowSchedule, StepTimesAddUpWithinTheCall) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  ShadowSchedule schedule(small_atlas);
  jobs::ThreadPool pool(2);
  for (jobs::ThreadPool* on : {static_cast<jobs::ThreadPool*>(nullptr), &pool}) {
    for (int call = 0; call < 3; ++call) {
      const auto start = std::chrono::steady_clock::now();
      schedule.schedule(lights, camera_at({0.0f, 5.0f, 2.0f}), {}, 0, on);
      const double call_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      double sum = 0.0;
      for (size_t step = 0; step < schedule_step_count; ++step) {
        EXPECT_GT(schedule.step_times()[step], 0.0) << schedule_step_names[step] << " not timed";
        sum += schedule.step_times()[step];
      }
      EXPECT_LE(sum, call_ms) << "call " << call;
    }
  }
}

TEST(ShadowSchedule, LightsOutOfSightGetNoShadow) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  ShadowSchedule schedule(small_atlas);
  // Far away and looking away: no bounded light's reach is in view; the sun still is.
  schedule.schedule(lights, camera_at({0.0f, 5.0f, -500.0f}), {}, 0);
  EXPECT_EQ(lights.maps[0].resolution, 0u);
  EXPECT_EQ(lights.maps[0].importance, 0.0f);
  EXPECT_GT(lights.maps[1].resolution, 0u);
  EXPECT_EQ(lights.cubes[0].resolution, 0u);
  EXPECT_EQ(lights.records[lights.maps[0].light].info.w, no_shadow_map);
  EXPECT_EQ(schedule.stats().lights_without_shadow, 3u);
}

// `count` spot lights looking down, 4 m apart in a row away from camera_at({0, 2, 0}), each
// reaching 3 m and asking for `resolution` texels.
scene::Scene spots_in_a_row(int count, uint32_t resolution) {
  scene::Scene scene;
  for (int i = 0; i < count; ++i) {
    const glm::vec3 position(0.0f, 2.0f, -3.0f - 4.0f * float(i));
    scene::SpotLight spot;
    spot.range = 3.0f;
    scene::add_light(
        scene, spot,
        {position, scene::look_rotation(position, position + glm::vec3(0, -1, 0)), glm::vec3(1.0f)},
        shadow_at(resolution), "spot " + std::to_string(i));
  }
  ecs::update_world_transforms(scene.world, 0);
  return scene;
}

// Twenty-four spot lights in a row away from the camera, each asking for 1024 texels, in an
// atlas of one 64-texel page (room for 16 of the smallest tiles): the nearest (largest on
// screen) keep the most texels, the farthest lose their shadow first.
TEST(ShadowSchedule, TheBudgetDegradesTheLeastImportantLightsFirst) {
  const scene::Scene scene = spots_in_a_row(24, 1024);
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  ShadowSchedule schedule(AtlasConfig{64, 1, min_shadow_resolution});
  schedule.schedule(lights, camera_at({0.0f, 2.0f, 0.0f}), {}, 0);
  ASSERT_EQ(lights.maps.size(), 24u);
  // Importance (size on screen) falls with distance; resolutions never grow with it, and the
  // budget left the farthest without a shadow.
  for (size_t i = 1; i < lights.maps.size(); ++i) {
    EXPECT_LT(lights.maps[i].importance, lights.maps[i - 1].importance) << "light " << i;
    EXPECT_LE(lights.maps[i].resolution, lights.maps[i - 1].resolution) << "light " << i;
  }
  EXPECT_GT(lights.maps.front().resolution, lights.maps.back().resolution);
  EXPECT_GT(schedule.stats().lights_without_shadow, 0u);
  EXPECT_EQ(lights.maps.back().resolution, 0u);
  EXPECT_EQ(lights.records[lights.maps.back().light].info.w, no_shadow_map);
  uint64_t texels = 0;
  for (const ShadowMapView& map : lights.maps) texels += uint64_t{map.resolution} * map.resolution;
  EXPECT_LE(texels, 64u * 64u);
}

// The time budget, told that every frame's shadow passes take far longer than it allows: first
// every light loses resolution down to its quality floor, never its shadow, then views wait their
// turn, each drawn again within a few frames; told the passes are quick again, it gives all back.
TEST(ShadowSchedule, TheTimeBudgetLowersResolutionsToTheFloorsThenDefersViews) {
  const scene::Scene scene = spots_in_a_row(24, 1024);
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);  // gathered once: every light stays changed
  ShadowSchedule schedule(AtlasConfig{4096, 16, min_shadow_resolution}, false, ShadowResolution::screen, 6.0);
  const ShadowCamera camera = camera_at({0.0f, 2.0f, 0.0f});
  // One frame, measured at once as taking `ms` of shadow passes.
  const auto frame = [&](double ms) {
    const uint64_t step = schedule.time_budget_step();
    schedule.schedule(lights, camera, {}, 0);
    schedule.measured(step, schedule.stats().views_rendered, ms);
  };
  frame(1.0);
  std::vector<uint32_t> full;
  for (const ShadowMapView& map : lights.maps) full.push_back(map.resolution);
  ASSERT_EQ(full.front(), 1024u);
  EXPECT_EQ(schedule.stats().lights_demoted_by_time, 0u);

  for (int i = 0; i < 100 && schedule.stats().views_deferred_by_time == 0; ++i) frame(60.0);
  const ShadowScheduleStats& stats = schedule.stats();
  EXPECT_GT(stats.lights_demoted_by_time, 0u);
  EXPECT_GT(stats.views_deferred_by_time, 0u) << "views wait once every light is at its floor";
  EXPECT_EQ(stats.lights_without_shadow, 0u) << "no light loses its shadow to time";
  EXPECT_EQ(stats.lights_demoted_by_memory, 0u);
  for (size_t m = 0; m < lights.maps.size(); ++m) {
    const uint32_t floor = quality_floor(algorithm_of(lights.records[lights.maps[m].light]));
    EXPECT_EQ(lights.maps[m].resolution, std::min(full[m], floor)) << "map " << m;
  }
  // At the smallest cap, each frame draws the stalest views it allows: every map comes round, once
  // in each 24 / cap frames.
  constexpr uint32_t cap = ShadowTimeBudget::min_view_cap;
  for (int i = 0; i < 100 && schedule.time_budget().limits().view_cap != cap; ++i) frame(60.0);
  ASSERT_EQ(schedule.time_budget().limits().view_cap, cap);
  std::vector<int> drawn(lights.maps.size(), 0);
  for (uint32_t i = 0; i < 24 / cap; ++i) {
    frame(60.0);
    EXPECT_EQ(schedule.stats().views_rendered, cap);
    for (size_t m = 0; m < lights.maps.size(); ++m) drawn[m] += lights.maps[m].render ? 1 : 0;
  }
  for (size_t m = 0; m < lights.maps.size(); ++m) EXPECT_EQ(drawn[m], 1) << "map " << m;

  for (int i = 0; i < 1000 && schedule.time_budget().limits() != ShadowTimeBudget::Limits{}; ++i) frame(0.5);
  frame(0.5);
  EXPECT_EQ(schedule.time_budget().limits(), ShadowTimeBudget::Limits{});
  EXPECT_EQ(schedule.stats().lights_demoted_by_time, 0u);
  EXPECT_EQ(schedule.stats().views_deferred_by_time, 0u);
  for (size_t m = 0; m < lights.maps.size(); ++m)
    EXPECT_EQ(lights.maps[m].resolution, full[m]) << "map " << m;
}

// A crate's box, 1 m wide, centred at z on the row of spots_in_a_row.
scene::Aabb crate_at(float z) {
  return scene::Aabb{glm::vec3(-0.5f, 0.0f, z - 0.5f), glm::vec3(0.5f, 1.0f, z + 0.5f)};
}

// Six spot lights 4 m apart, each reaching 3 m, scheduled frame after frame.
struct SpotsInARow {
  scene::Scene scene = spots_in_a_row(6, 64);
  FrameLights lights;
  ShadowSchedule schedule{small_atlas};

  // One frame: the lights gathered and scheduled with `casters`; the maps drawn.
  std::vector<int> maps_drawn(const CasterUpdate& casters) {
    scene.world.advance_tick();
    gather_lights(scene.world, bounds, {}, lights);
    schedule.schedule(lights, camera_at({0.0f, 2.0f, 0.0f}), casters, 0);
    std::vector<int> drawn;
    for (size_t m = 0; m < lights.maps.size(); ++m) {
      if (lights.maps[m].render) drawn.push_back(static_cast<int>(m));
    }
    return drawn;
  }
  // The same with the frame's one caster, a crate at z, told whole.
  std::vector<int> maps_drawn_with_crate_at(float z) {
    const std::vector<CasterBounds> casters{{7, crate_at(z)}};
    return maps_drawn(std::span<const CasterBounds>(casters));
  }
};

// Moving a crate from the first light's reach into the second's redraws exactly those two maps;
// a frame where nothing moves redraws none.
TEST(ShadowSchedule, AMovedCasterRedrawsExactlyTheLightsItReaches) {
  SpotsInARow row;
  EXPECT_EQ(row.maps_drawn_with_crate_at(-3.0f).size(), 6u);  // every map is new
  EXPECT_TRUE(row.maps_drawn_with_crate_at(-3.0f).empty());
  EXPECT_EQ(row.maps_drawn_with_crate_at(-7.0f), (std::vector<int>{0, 1}));
  EXPECT_TRUE(row.maps_drawn_with_crate_at(-7.0f).empty());
  EXPECT_EQ(row.schedule.stats().views_cached, 6u);
}

// The same move told as the boxes that changed (a caller that knows what moved) redraws the
// same two maps; and a later frame told whole only reports what changed since it last saw all.
TEST(ShadowSchedule, ChangedBoxesRedrawWhatTheWholeListWould) {
  SpotsInARow row;
  EXPECT_EQ(row.maps_drawn_with_crate_at(-3.0f).size(), 6u);  // every map is new
  const std::vector<scene::Aabb> moved{crate_at(-3.0f), crate_at(-7.0f)};
  EXPECT_EQ(row.maps_drawn(CasterUpdate::changes(moved)), (std::vector<int>{0, 1}));
  EXPECT_TRUE(row.maps_drawn(CasterUpdate::changes({})).empty());
  EXPECT_EQ(row.maps_drawn_with_crate_at(-7.0f), (std::vector<int>{0, 1}))
      << "the tracker last saw the crate at the first place: it reports the move again";
  EXPECT_TRUE(row.maps_drawn_with_crate_at(-7.0f).empty());
}

// Scheduling on a thread pool splits the views into pieces; the result must not depend on it.
// With static layers, a crate that keeps moving redraws the maps it crosses with the moving
// casters alone; the first move, which takes it out of the layers, redraws them with every
// caster. A map whose light moved draws every caster again.
TEST(ShadowSchedule, MovingCastersAloneRedrawOverStaticLayers) {
  SpotsInARow row;
  row.schedule = ShadowSchedule(small_atlas, true);
  const auto moving_only = [&] {
    std::vector<int> maps;
    for (size_t m = 0; m < row.lights.maps.size(); ++m) {
      if (row.lights.maps[m].moving_casters_only) maps.push_back(static_cast<int>(m));
    }
    return maps;
  };
  EXPECT_EQ(row.maps_drawn(CasterUpdate::changes({})).size(), 6u);
  EXPECT_TRUE(moving_only().empty()) << "new maps";
  const std::vector<scene::Aabb> first_move{crate_at(-3.0f)};
  const std::vector<scene::Aabb> moved{crate_at(-7.0f)};
  EXPECT_EQ(row.maps_drawn(CasterUpdate::changes(first_move, moved)), (std::vector<int>{0, 1}));
  EXPECT_EQ(moving_only(), (std::vector<int>{1})) << "the layer of map 0 held the crate, map 1's never did";
  const std::vector<scene::Aabb> back{crate_at(-7.0f), crate_at(-3.0f)};
  EXPECT_EQ(row.maps_drawn(CasterUpdate::changes({}, back)), (std::vector<int>{0, 1}));
  EXPECT_EQ(moving_only(), (std::vector<int>{0, 1}));
  EXPECT_EQ(row.schedule.stats().views_moving_only, 2u);

  ecs::World& world = row.scene.world;
  const ecs::Tick before = world.tick();
  world.advance_tick();
  ecs::Entity light_0;
  world.query<const scene::SpotLight, const ecs::LocalTransform>().for_each(
      [&](ecs::Entity entity, const scene::SpotLight&, const ecs::LocalTransform& local) {
        if (local.translation.z == -3.0f) light_0 = entity;
      });
  world.get_mut<ecs::LocalTransform>(light_0).translation.y += 0.5f;
  ecs::update_world_transforms(world, before);
  EXPECT_EQ(row.maps_drawn(CasterUpdate::changes({}, back)), (std::vector<int>{0, 1}));
  EXPECT_EQ(moving_only(), (std::vector<int>{1})) << "light 0 moved";
}

// A map drawn over its static layer uses the view that layer was drawn with, its own light's,
// also when the frame's lights come in another order (the same count, two swapped).
TEST(ShadowSchedule, MovingCastersRedrawWithTheirOwnLightsLayerViewAfterAReorder) {
  SpotsInARow row;
  row.schedule = ShadowSchedule(small_atlas, true);
  EXPECT_EQ(row.maps_drawn(CasterUpdate::changes({})).size(), 6u);
  std::map<uint64_t, glm::mat4> drawn_with;
  for (const ShadowMapView& map : row.lights.maps) drawn_with[map.key] = map.view.view_projection();

  row.scene.world.advance_tick();
  gather_lights(row.scene.world, bounds, {}, row.lights);
  std::swap(row.lights.maps[0], row.lights.maps[1]);
  const std::vector<scene::Aabb> moving{crate_at(-7.0f), crate_at(-3.0f)};
  row.schedule.schedule(row.lights, camera_at({0.0f, 2.0f, 0.0f}), CasterUpdate::changes({}, moving), 0);
  for (const size_t m : {0u, 1u}) {
    const ShadowMapView& map = row.lights.maps[m];
    ASSERT_TRUE(map.moving_casters_only) << "map " << m;
    EXPECT_EQ(map.view.view_projection(), drawn_with.at(map.key)) << "map " << m;
  }
}

// A long-lived FrameLights, scheduled and sorted every frame as the renderer does, keeps the
// views and records of lights nothing wrote to; what it gathers must equal a fresh gather, frame
// after frame, through moves, edits, renames, a name removed, a shadow switched off (a new list),
// and directional and cylinder views that follow the scene's bounds. (Frame 1 sees every
// transform as changed: frame 0 wrote them in the tick it gathered in.)
TEST(FrameLights, AGatherKeepingUnchangedLightsEqualsAFreshGather) {
  scene::Scene scene;
  std::vector<ecs::Entity> lights;
  for (int i = 0; i < 300; ++i) {
    const ecs::LocalTransform at{glm::vec3(float(i % 20), 3.0f, -float(i / 20))};
    const scene::ShadowSettings shadow = shadow_at(64u << (i % 3), i % 11 != 0);
    const std::string name = i % 4 == 0 ? "" : "light " + std::to_string(i);
    if (i % 2 == 0) lights.push_back(scene::add_light(scene, scene::PointLight{}, at, shadow, name));
    if (i % 2 == 1) lights.push_back(scene::add_light(scene, scene::SpotLight{}, at, shadow, name));
  }
  scene::ShadowSettings sun = shadow_at(512);
  sun.cascades = 3;
  scene::add_light(scene, scene::DirectionalLight{}, above, sun, "sun");
  scene::add_light(scene, scene::CylinderLight{}, above, shadow_at(512), "");
  ecs::World& world = scene.world;
  ecs::update_world_transforms(world, 0);
  jobs::ThreadPool pool(3);
  FrameLights kept;
  ShadowSchedule schedule(AtlasConfig{2048, 4, min_shadow_resolution}, true);
  std::mt19937 random(3);
  ecs::Tick transforms_at = 0;
  scene::Aabb scene_bounds = bounds;
  std::set<uint64_t> edited_now;
  for (int frame = 0; frame < 10; ++frame) {
    world.advance_tick();
    // `changed` is a write since the last gather's tick, which the last frame's writes share.
    std::set<uint64_t> edited = std::exchange(edited_now, {});
    if (frame > 0) {
      for (int k = 0; k < 12; ++k) {
        const ecs::Entity light = lights[random() % lights.size()];
        if (k % 4 != 3) edited_now.insert(light_key(light));  // a name is no change to the light
        switch (k % 4) {
          case 0: world.get_mut<ecs::LocalTransform>(light).translation.y += 0.5f; break;
          case 1:
            if (world.has<scene::SpotLight>(light)) world.get_mut<scene::SpotLight>(light).range += 1.0f;
            if (world.has<scene::PointLight>(light)) world.get_mut<scene::PointLight>(light).range += 1.0f;
            break;
          case 2:  // on some frames only: the others reuse the last gather's list
            if (frame % 3 == 0) world.get_mut<scene::ShadowSettings>(light).resolution *= 2;
            if (frame % 3 != 0) world.get_mut<ecs::LocalTransform>(light).translation.x += 0.5f;
            break;
          case 3:
            if (world.has<scene::Name>(light)) world.get_mut<scene::Name>(light).value += "'";
            break;
        }
      }
    }
    if (frame == 4) world.remove<scene::Name>(lights[1]);  // renamed by its kind and index
    if (frame == 5) world.get_mut<scene::ShadowSettings>(lights[2]).casts_shadow = false;
    if (frame == 7) {
      edited_now.insert(light_key(scene::add_light(scene, scene::SpotLight{}, above, shadow_at(256), "new")));
    }
    if (frame == 8) {
      world.destroy(lights.back());
      lights.pop_back();
    }
    scene_bounds.max.x += 1.0f;  // the directional and cylinder views follow it
    ecs::update_world_transforms(world, transforms_at);
    transforms_at = world.tick();
    edited.insert(edited_now.begin(), edited_now.end());

    gather_lights(world, scene_bounds, {}, kept, &pool);
    FrameLights fresh;
    gather_lights(world, scene_bounds, {}, fresh);
    SCOPED_TRACE("frame " + std::to_string(frame));
    ASSERT_EQ(kept.records.size(), fresh.records.size());
    for (size_t i = 0; i < fresh.records.size(); ++i) {  // the shadow fields are the schedule's
      const GpuLight kept_record = with_shadow_fields_of(kept.records[i], fresh.records[i]);
      EXPECT_EQ(std::memcmp(&kept_record, &fresh.records[i], sizeof(GpuLight)), 0) << "record " << i;
    }
    ASSERT_EQ(kept.maps.size(), fresh.maps.size());
    ASSERT_EQ(kept.cubes.size(), fresh.cubes.size());
    ASSERT_EQ(kept.cascaded.size(), fresh.cascaded.size());
    for (size_t c = 0; c < fresh.cascaded.size(); ++c) {
      EXPECT_EQ(kept.cascaded[c].record, fresh.cascaded[c].record);
      EXPECT_EQ(kept.cascaded[c].first_view, fresh.cascaded[c].first_view);
    }
    // What gathering sets in a map's or a cube's view alike.
    const auto expect_same_view = [&](const auto& kept_view, const auto& fresh_view,
                                      const std::string& which) {
      EXPECT_EQ(kept_view.light, fresh_view.light) << which;
      EXPECT_EQ(kept_view.key, fresh_view.key) << which;
      EXPECT_EQ(kept_view.name, fresh_view.name) << which;
      EXPECT_EQ(kept_view.requested_resolution, fresh_view.requested_resolution) << which;
    };
    for (size_t m = 0; m < fresh.maps.size(); ++m) {
      const std::string which = "map " + std::to_string(m);
      expect_same_view(kept.maps[m], fresh.maps[m], which);
      EXPECT_EQ(kept.maps[m].reach, fresh.maps[m].reach) << which;
      if (fresh.maps[m].cascade == no_cascade) {  // place_cascades places the cascades' views
        EXPECT_EQ(kept.maps[m].view.view_projection(), fresh.maps[m].view.view_projection()) << which;
      }
      if (frame > 1 && kept.maps[m].reach.w > 0.0f) {
        EXPECT_EQ(kept.maps[m].changed, edited.contains(kept.maps[m].key)) << which;
      }
    }
    for (size_t c = 0; c < fresh.cubes.size(); ++c) {
      const std::string which = "cube " + std::to_string(c);
      expect_same_view(kept.cubes[c], fresh.cubes[c], which);
      EXPECT_EQ(kept.cubes[c].position_far, fresh.cubes[c].position_far) << which;
      if (frame > 1) {
        EXPECT_EQ(kept.cubes[c].changed, edited.contains(kept.cubes[c].key)) << which;
      }
    }
    if (HasFailure()) return;
    // As the renderer goes on: moving crates redraw maps over their static layers.
    const std::vector<scene::Aabb> moving{crate_at(-2.0f - float(frame)), crate_at(-3.0f - float(frame))};
    schedule.schedule(kept, camera_at({10.0f, 10.0f, 5.0f}), CasterUpdate::changes({}, moving), 200, &pool);
    sorted_by_group(kept, &pool);
  }
}

// Records kept from frame to frame, written only where a map was drawn, moved or lost, hold what
// writing every shadowed record every frame gives: through lights moving, a camera flying past
// (maps in and out of sight, up and down in resolution), an atlas too small for them all, moving
// casters and a view budget that defers redraws.
TEST(ShadowSchedule, KeptRecordsHoldWhatWritingEveryRecordGives) {
  scene::Scene scene;
  std::vector<ecs::Entity> lights;
  for (int i = 0; i < 400; ++i) {
    const ecs::LocalTransform at{glm::vec3(float(i % 20) * 2.0f, 3.0f, -float(i / 20) * 2.0f)};
    const scene::ShadowSettings shadow = shadow_at(64u << (i % 4), i % 9 != 0);
    if (i % 2 == 0) lights.push_back(scene::add_light(scene, scene::PointLight{}, at, shadow, ""));
    if (i % 2 == 1) lights.push_back(scene::add_light(scene, scene::SpotLight{}, at, shadow, ""));
  }
  ecs::World& world = scene.world;
  ecs::update_world_transforms(world, 0);
  FrameLights skipping, writing;
  std::vector<GpuLight> skipping_sorted, writing_sorted;
  ShadowSchedule skipping_schedule(AtlasConfig{1024, 2, min_shadow_resolution}, true);
  ShadowSchedule writing_schedule(AtlasConfig{1024, 2, min_shadow_resolution}, true);
  std::mt19937 random(5);
  ecs::Tick transforms_at = 0;
  size_t written_less = 0;
  for (int frame = 0; frame < 40; ++frame) {
    world.advance_tick();
    for (int k = 0; k < 10; ++k) {
      world.get_mut<ecs::LocalTransform>(lights[random() % lights.size()]).translation.y += 0.25f;
    }
    ecs::update_world_transforms(world, transforms_at);
    transforms_at = world.tick();
    const ShadowCamera camera = camera_at({float(frame) - 10.0f, 6.0f, 10.0f - float(frame)});
    const std::vector<scene::Aabb> moving{crate_at(-float(frame % 20) * 2.0f)};
    for (auto [lights_now, schedule, sorted, write_all] :
         {std::tuple(&skipping, &skipping_schedule, &skipping_sorted, false),
          std::tuple(&writing, &writing_schedule, &writing_sorted, true)}) {
      gather_lights(world, bounds, {}, *lights_now);
      if (write_all) lights_now->refilled.assign(lights_now->records.size(), 1);
      if (!write_all)
        written_less += size_t(std::count(lights_now->refilled.begin(), lights_now->refilled.end(), 0));
      schedule->schedule(*lights_now, camera, CasterUpdate::changes({}, moving), 60);
      *sorted = sorted_by_group(*lights_now);
    }
    SCOPED_TRACE("frame " + std::to_string(frame));
    // A record has a map exactly where its view has one.
    for (const ShadowMapView& map : skipping.maps) {
      ASSERT_EQ(skipping.records[map.light].info.w == no_shadow_map, map.resolution == 0) << map.key;
    }
    for (const ShadowCubeView& cube : skipping.cubes) {
      ASSERT_EQ(skipping.records[cube.light].info.w == no_shadow_map, cube.resolution == 0) << cube.key;
    }
    ASSERT_EQ(skipping.records.size(), writing.records.size());
    for (size_t i = 0; i < writing.records.size(); ++i) {
      ASSERT_EQ(std::memcmp(&skipping.records[i], &writing.records[i], sizeof(GpuLight)), 0)
          << "record " << i;
    }
    EXPECT_EQ(
        std::memcmp(skipping_sorted.data(), writing_sorted.data(), writing_sorted.size() * sizeof(GpuLight)),
        0);
    EXPECT_EQ(skipping.sorted_place, writing.sorted_place);
    EXPECT_EQ(skipping.group_begin, writing.group_begin);
  }
  EXPECT_GT(written_less, 0u);
  EXPECT_GT(skipping_schedule.stats().lights_without_shadow, 0u)
      << "the atlas too small, or lights out of sight";
}

TEST(ShadowSchedule, AThreadPoolSchedulesTheSameShadows) {
  scene::Scene scene;
  for (int i = 0; i < 900; ++i) {  // several pieces of maps and of cubes, resolutions mixed
    const ecs::LocalTransform at{glm::vec3(float(i % 30), 3.0f, -float(i / 30))};
    const scene::ShadowSettings shadow = shadow_at(64u << (i % 4), i % 7 != 0);
    if (i % 2 == 0) scene::add_light(scene, scene::PointLight{}, at, shadow, "");
    if (i % 2 == 1) scene::add_light(scene, scene::SpotLight{}, at, shadow, "");
  }
  ecs::update_world_transforms(scene.world, 0);
  const ShadowCamera camera = camera_at({15.0f, 10.0f, 5.0f});
  jobs::ThreadPool pool(3);
  FrameLights serial;
  FrameLights pooled;
  ShadowSchedule serial_schedule(AtlasConfig{2048, 4, min_shadow_resolution});
  ShadowSchedule pooled_schedule(AtlasConfig{2048, 4, min_shadow_resolution});
  // Frame one draws every map it can; in frame two crates move, and some of the maps they reach
  // are drawn again within a budget of views.
  for (const float crate_z : {-3.0f, -12.0f}) {
    std::vector<CasterBounds> casters;
    for (int k = 0; k < 20; ++k) casters.push_back({uint64_t(k), crate_at(crate_z - float(k))});
    for (auto [lights, schedule, pool_used] :
         {std::tuple(&serial, &serial_schedule, (jobs::ThreadPool*)nullptr),
          std::tuple(&pooled, &pooled_schedule, &pool)}) {
      gather_lights(scene.world, bounds, {}, *lights);
      schedule->schedule(*lights, camera, std::span<const CasterBounds>(casters), 200, pool_used);
    }
    ASSERT_EQ(pooled.records.size(), serial.records.size());
    EXPECT_EQ(
        std::memcmp(pooled.records.data(), serial.records.data(), serial.records.size() * sizeof(GpuLight)),
        0);
    for (size_t m = 0; m < serial.maps.size(); ++m) {
      EXPECT_EQ(pooled.maps[m].resolution, serial.maps[m].resolution);
      EXPECT_EQ(pooled.maps[m].render, serial.maps[m].render);
      EXPECT_EQ(pooled.maps[m].importance, serial.maps[m].importance);
    }
    for (size_t c = 0; c < serial.cubes.size(); ++c) {
      EXPECT_EQ(pooled.cubes[c].resolution, serial.cubes[c].resolution);
      EXPECT_EQ(pooled.cubes[c].render, serial.cubes[c].render);
    }
    const ShadowScheduleStats& a = serial_schedule.stats();
    const ShadowScheduleStats& b = pooled_schedule.stats();
    EXPECT_EQ(a.views_rendered, b.views_rendered);
    EXPECT_EQ(a.views_cached, b.views_cached);
    EXPECT_EQ(a.lights_without_shadow, b.lights_without_shadow);
    EXPECT_EQ(a.lights_waiting, b.lights_waiting);
    EXPECT_EQ(a.lights_per_resolution, b.lights_per_resolution);
    EXPECT_GT(a.views_rendered, 0u);
    EXPECT_GT(a.lights_per_resolution.size(), 1u);
  }
  EXPECT_GT(serial_schedule.stats().views_cached, 0u);
  EXPECT_GT(serial_schedule.stats().lights_waiting, 0u);
}

// five_lights() gathered, given maps from above and sorted by group.
struct FiveLightsByGroup {
  FrameLights lights;
  std::vector<GpuLight> sorted;
};
FiveLightsByGroup five_lights_by_group() {
  const scene::Scene scene = five_lights();
  FiveLightsByGroup out;
  gather_lights(scene.world, bounds, {}, out.lights);
  ShadowSchedule schedule(small_atlas);
  schedule.schedule(out.lights, camera_at({0.0f, 5.0f, 2.0f}), {}, 0);
  out.sorted = sorted_by_group(out.lights);
  return out;
}

TEST(FrameLights, RecordsAreOrderedByLightGroup) {
  const auto [lights, sorted] = five_lights_by_group();
  // Every light here uses pcf: "fill" is unshadowed, key and the sun have 2D maps, two cubes.
  const uint32_t map_pcf = light_group(ShadowKind::map, scene::ShadowAlgorithm::pcf);
  const uint32_t cube_pcf = light_group(ShadowKind::cube, scene::ShadowAlgorithm::pcf);
  EXPECT_EQ(lights.group_begin[0], 0u);
  EXPECT_EQ(lights.group_begin[1], 1u);  // one unshadowed light
  EXPECT_EQ(lights.group_begin[map_pcf + 1] - lights.group_begin[map_pcf], 2u);
  EXPECT_EQ(lights.group_begin[cube_pcf + 1] - lights.group_begin[cube_pcf], 2u);
  EXPECT_EQ(lights.group_begin[light_group_count], 5u);
  for (const ShadowMapView& map : lights.maps) {
    EXPECT_GE(lights.sorted_place[map.light], lights.group_begin[map_pcf]);
    EXPECT_LT(lights.sorted_place[map.light], lights.group_begin[map_pcf + 1]);
  }
  for (const ShadowCubeView& cube : lights.cubes) {
    EXPECT_EQ(lights.records[cube.light].info.x, uint32_t(GpuLightType::point));
    EXPECT_GE(lights.sorted_place[cube.light], lights.group_begin[cube_pcf]);
    EXPECT_EQ(
        std::memcmp(&sorted[lights.sorted_place[cube.light]], &lights.records[cube.light], sizeof(GpuLight)),
        0);
  }
  // Each group's light types: its lights' light_type_bits, none for an empty group.
  const auto bit = [](GpuLightType type) { return 1u << uint32_t(type); };
  for (uint32_t group = 0; group < light_group_count; ++group) {
    uint32_t types = 0;
    for (uint32_t i = lights.group_begin[group]; i < lights.group_begin[group + 1]; ++i) {
      types |= light_type_bits(sorted[i]);
    }
    EXPECT_EQ(lights.group_types[group], types) << "group " << group;
  }
  EXPECT_EQ(lights.group_types[cube_pcf], bit(GpuLightType::point));
  EXPECT_EQ(lights.group_types[map_pcf] & bit(GpuLightType::point), 0u);
  // Groups number the same on both sides of the shader boundary.
  for (uint32_t group = 0; group < light_group_count; ++group) {
    if (group_shadow_kind(group) == ShadowKind::none) continue;
    EXPECT_EQ(light_group(group_shadow_kind(group), group_algorithm(group)), group);
  }
}

// What a shader shading every group at once is specialized on: the groups with lights, those with
// one, their light types together and each 2D group's own.
TEST(FrameLights, GroupsPresentAreTheGroupsWithLightsAndThoseWithOne) {
  const FrameLights lights = five_lights_by_group().lights;
  const GroupsPresent groups = groups_present(lights.group_begin, lights.group_types);
  const uint32_t map_pcf = light_group(ShadowKind::map, scene::ShadowAlgorithm::pcf);
  const uint32_t cube_pcf = light_group(ShadowKind::cube, scene::ShadowAlgorithm::pcf);
  EXPECT_EQ(groups.present, 1u | 1u << map_pcf | 1u << cube_pcf);
  EXPECT_EQ(groups.single, 1u) << "the unshadowed light alone; two maps and two cubes";
  uint32_t types = 0;
  for (const GpuLight& record : lights.records) types |= light_type_bits(record);
  EXPECT_EQ(groups.light_types, types);
  EXPECT_NE(groups.light_types & 1u << uint32_t(GpuLightType::point), 0u);
  for (uint32_t group = 0; group < groups_with_own_types; ++group) {
    EXPECT_EQ((groups.group_types >> 5 * group) & 0x1Fu, lights.group_types[group]) << "group " << group;
  }
  EXPECT_NE((groups.group_types >> 5 * map_pcf) & 0x1Fu, 0u) << "the key light and the sun";
  // Each field the shaders take apart from the types together changes the key.
  for (GroupsPresent other :
       {GroupsPresent{groups.present ^ 2u, groups.single, groups.light_types, groups.group_types},
        GroupsPresent{groups.present, groups.single ^ 2u, groups.light_types, groups.group_types},
        GroupsPresent{groups.present, groups.single, groups.light_types, groups.group_types ^ 1u}}) {
    EXPECT_NE(other.key(), groups.key());
  }
}

// A shader's group slots (shaders/group_slots.glsl): the groups in order, four bits each, the
// slots past the last holding 15, so that a set of fewer groups than slots shades nothing more.
TEST(FrameLights, GroupSlotsListTheGroupsInOrder) {
  EXPECT_EQ(group_slot_list(1u << 3), 0xFFFFFFF3u);
  EXPECT_EQ(group_slot_list(1u | 1u << 6 | 1u << 10), 0xFFFFFA60u);
  EXPECT_EQ(group_slot_list(0u), 0xFFFFFFFFu);
  // The first eight of more groups.
  EXPECT_EQ(group_slot_list((1u << light_group_count) - 1u), 0x76543210u);
}

// Sorting on a thread pool moves every record where the serial sort does: 5,000 records of
// every group, their indices in the position field so that each can be followed.
TEST(SortByGroup, OnAThreadPoolMovesTheRecordsAsSerially) {
  FrameLights serial;
  for (uint32_t i = 0; i < 5000; ++i) {
    GpuLight record;
    record.position_range = glm::vec4(float(i), 0.0f, 0.0f, 1.0f);
    record.info = {(i * 7) % 4, 0u, (i * 3) % 5, i % 3 == 0 ? no_shadow_map : 0u};
    serial.records.push_back(record);
  }
  FrameLights pooled = serial;
  const std::vector<GpuLight> serial_sorted = sorted_by_group(serial);
  jobs::ThreadPool pool(4);
  const std::vector<GpuLight> pooled_sorted = sorted_by_group(pooled, &pool);
  EXPECT_EQ(pooled.group_begin, serial.group_begin);
  EXPECT_EQ(pooled.group_types, serial.group_types);
  EXPECT_EQ(pooled.sorted_place, serial.sorted_place);
  EXPECT_EQ(std::memcmp(pooled_sorted.data(), serial_sorted.data(), serial_sorted.size() * sizeof(GpuLight)),
            0);
  // Within each group the lights keep their order (the serial sort's groups are tested above).
  for (uint32_t group = 0; group < light_group_count; ++group) {
    for (uint32_t i = pooled.group_begin[group] + 1; i < pooled.group_begin[group + 1]; ++i) {
      EXPECT_LT(pooled_sorted[i - 1].position_range.x, pooled_sorted[i].position_range.x) << i;
    }
  }
  EXPECT_GT(pooled.group_begin[light_group_count - 1], pooled.group_begin[1]);  // several groups
}

// With changes asked for, a sort over the last sort's records marks the places whose record
// changed, and only those (the renderer writes only them into the slots' buffers), on one thread
// or several; where a record changes group, the records between its places move too.
TEST(SortByGroup, MarksThePlacesWhoseRecordChanged) {
  FrameLights lights;
  for (uint32_t i = 0; i < 3000; ++i) {
    GpuLight record;
    record.position_range = glm::vec4(float(i), 0.0f, 0.0f, 1.0f);
    record.info = {i % 2, 0u, 1u, 0u};
    lights.records.push_back(record);
  }
  jobs::ThreadPool pool(4);
  for (jobs::ThreadPool* p : {static_cast<jobs::ThreadPool*>(nullptr), &pool}) {
    std::vector<GpuLight> sorted(lights.records.size());
    std::vector<uint64_t> changed_at(lights.records.size(), 0);
    sort_by_group(lights, sorted, p, {changed_at, 1});
    EXPECT_EQ(std::count(changed_at.begin(), changed_at.end(), 1u), 3000);
    EXPECT_EQ(std::memcmp(sorted.data(), sorted_by_group(lights).data(), sorted.size() * sizeof(GpuLight)),
              0);

    sort_by_group(lights, sorted, p, {changed_at, 2});
    EXPECT_EQ(std::count(changed_at.begin(), changed_at.end(), 2u), 0) << "nothing changed";

    FrameLights moved = lights;
    moved.records[10].color_intensity.a = 3.0f;
    sort_by_group(moved, sorted, p, {changed_at, 3});
    EXPECT_EQ(std::count(changed_at.begin(), changed_at.end(), 3u), 1);
    EXPECT_EQ(changed_at[moved.sorted_place[10]], 3u);
    EXPECT_EQ(sorted[moved.sorted_place[10]].color_intensity.a, 3.0f);

    // Record 0, the first point light with pcf, takes pcss with noise, the last group: the
    // other 1,499 move up a place, and it takes the last.
    moved.records[0].info.z = 4u;
    const std::vector<GpuLight> before = sorted;
    sort_by_group(moved, sorted, p, {changed_at, 4});
    EXPECT_EQ(std::count(changed_at.begin(), changed_at.end(), 4u), 1500);
    for (size_t place = 0; place < sorted.size(); ++place) {
      const bool differs = std::memcmp(&before[place], &sorted[place], sizeof(GpuLight)) != 0;
      EXPECT_EQ(changed_at[place] == 4u, differs) << place;
    }
    EXPECT_EQ(std::memcmp(sorted.data(), sorted_by_group(moved).data(), sorted.size() * sizeof(GpuLight)), 0);
  }
}

}  // namespace
}  // namespace sg::shadows
