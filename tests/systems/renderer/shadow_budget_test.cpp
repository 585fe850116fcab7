// SPDX-License-Identifier: MIT
// The shadows' time budget in the renderer, on lavapipe: off on a CPU device unless set, and,
// set, learning from the shadow times handed to it. The times are given, not measured, so that
// no result depends on how fast lavapipe runs; the renderer prepares frames without submitting
// them.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "systems/frame/frame.h"
#include "systems/frame/scene_view.h"
#include "systems/renderer/scene_renderer.h"
#include "systems/shadows/quality_floor.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 320;
constexpr uint32_t height = 180;
constexpr uint32_t frames_in_flight = 2;

using ShadowBudget = GpuTest;

TEST_F(ShadowBudget, IsOffOnACpuDeviceUnlessSet) {
  ASSERT_EQ(context.properties().deviceType, VK_PHYSICAL_DEVICE_TYPE_CPU);
  FrameSettings options;
  const SceneView view = load_scene_view(options, float(width) / height);
  EXPECT_FALSE(SceneRenderer(context, view.scene, frames_in_flight, frame_format, options.renderer)
                   .shadow_time_budget()
                   .on());
  options.renderer.shadow_budget_ms = 2.5f;
  const SceneRenderer budgeted(context, view.scene, frames_in_flight, frame_format, options.renderer);
  EXPECT_TRUE(budgeted.shadow_time_budget().on());
  EXPECT_EQ(budgeted.shadow_time_budget().budget_ms(), 2.5);
  EXPECT_FALSE(
      SceneRenderer(context, view.scene, frames_in_flight, frame_format, naive_baseline(options.renderer))
          .shadow_time_budget()
          .on())
      << "the naive baseline has none";
}

// Shadow passes far over the budget take every light of the default scene down to its quality
// floor, none without its shadow; quick ones give the resolutions back.
TEST_F(ShadowBudget, SlowShadowPassesLowerTheLightsToTheirFloorsAndQuickOnesRestoreThem) {
  FrameSettings options;
  options.renderer.shadow_budget_ms = 2.0f;
  SceneView view = load_scene_view(options, float(width) / height);
  SceneRenderer renderer(context, view.scene, frames_in_flight, frame_format, options.renderer);
  uint32_t slot = 0;
  // One frame prepared, its shadow passes said to take `ms`.
  const auto frame = [&](double ms) {
    renderer.gather(view.scene.world);
    renderer.prepare(slot, view.pose, view.lens, width, height);
    slot = (slot + 1) % frames_in_flight;
    renderer.measured_shadow_ms(ms, renderer.shadow_work());
  };
  frame(1.0);
  std::vector<uint32_t> full;
  for (const shadows::ShadowMapView& map : renderer.lights().maps) full.push_back(map.resolution);
  for (const shadows::ShadowCubeView& cube : renderer.lights().cubes) full.push_back(cube.resolution);
  ASSERT_GT(*std::max_element(full.begin(), full.end()), 128u) << "some light above every floor";
  EXPECT_EQ(renderer.shadow_stats().lights_demoted_by_time, 0u);

  for (int i = 0; i < 60; ++i) frame(50.0);
  EXPECT_GT(renderer.shadow_time_budget().limits().lowered_tiers, 0.0f);
  EXPECT_GT(renderer.shadow_stats().lights_demoted_by_time, 0u);
  EXPECT_EQ(renderer.shadow_stats().lights_without_shadow, 0u);
  size_t v = 0;
  const shadows::FrameLights& lights = renderer.lights();
  const auto floor = [&](uint32_t light) {
    return shadows::quality_floor(shadows::algorithm_of(lights.records[light]));
  };
  for (const shadows::ShadowMapView& map : lights.maps) {
    EXPECT_EQ(map.resolution, std::min(full[v++], floor(map.light))) << map.name;
  }
  for (const shadows::ShadowCubeView& cube : lights.cubes) {
    EXPECT_EQ(cube.resolution, std::min(full[v++], floor(cube.light))) << cube.name;
  }

  for (int i = 0; i < 200 && renderer.shadow_time_budget().limits().lowered_tiers > 0.0f; ++i) frame(0.1);
  frame(0.1);
  EXPECT_EQ(renderer.shadow_time_budget().limits(), shadows::ShadowTimeBudget::Limits{});
  EXPECT_EQ(renderer.shadow_stats().lights_demoted_by_time, 0u);
  v = 0;
  for (const shadows::ShadowMapView& map : lights.maps) EXPECT_EQ(map.resolution, full[v++]) << map.name;
  for (const shadows::ShadowCubeView& cube : lights.cubes) EXPECT_EQ(cube.resolution, full[v++]) << cube.name;
}

}  // namespace
}  // namespace sg::test
