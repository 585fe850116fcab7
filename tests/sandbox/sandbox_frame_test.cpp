// SPDX-License-Identifier: MIT
// The sandbox's additions to the frame on lavapipe with validation and synchronization validation
// on (GpuTest fails on any report): the panels, the light heat map and the depth overlay (the
// render graph's extension example).
#include <algorithm>
#include <array>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "sandbox/sandbox_frame.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/headless_frames.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"
#include "systems/scene/shadow_requests.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/shadow_resolution.h"
#include "tests/support/frame_checks.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 128;
constexpr uint32_t height = 96;

class SandboxFrameTest : public GpuTest {
 protected:
  // Renders `frame_count` frames of `options`'s scene and returns the last picture.
  vk::Rgba8Image render(const sandbox::Options& options, uint32_t frame_count) {
    SceneView scene = load_scene_view(options.frame, float(width) / height);
    vk::FrameRing frames(context);
    sandbox::SandboxFrame sandbox_frame(context, scene, options, frames.frames_in_flight());
    Frame& frame = sandbox_frame.frame();
    sandbox_frame.fit({width, height}, false);
    scene_extent = frame.scene_extent();
    GpuTimeLog gpu_times;
    render_headless_frames(frame, frames, frame_count, gpu_times);
    passes = executed_passes(*frame.plan());
    return vk::read_rgba8(context, frame.image());
  }

  std::vector<std::string> passes;
  VkExtent2D scene_extent{};
};

// The pixels where `colored` differs from `plain` by more than a level.
std::vector<bool> changed_pixels(const vk::Rgba8Image& plain, const vk::Rgba8Image& colored) {
  std::vector<bool> changed;
  for (uint32_t y = 0; y < plain.height; ++y) {
    for (uint32_t x = 0; x < plain.width; ++x) {
      bool differs = false;
      for (int c = 0; c < 3; ++c) differs |= std::abs(int(plain.at(x, y)[c]) - int(colored.at(x, y)[c])) > 1;
      changed.push_back(differs);
    }
  }
  return changed;
}

// --ui: Dear ImGui's panels drawn by the frame's own "ui" pass, headless (no input), over the
// picture and under validation; without it the picture is untouched.
TEST_F(SandboxFrameTest, PanelsDrawOverThePicture) {
  const vk::Rgba8Image plain = render(sandbox::Options{}, 2);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "ui"), 0);
  sandbox::Options with_panels;
  with_panels.ui = true;
  const vk::Rgba8Image panels = render(with_panels, 2);
  EXPECT_EQ(passes.back(), "ui");
  // The frame-facts panel's title bar sits in the top-left corner.
  int differing = 0;
  for (uint32_t y = 8; y < 24; ++y) {
    for (uint32_t x = 8; x < 64; ++x)
      differing += !std::equal(plain.at(x, y), plain.at(x, y) + 3, panels.at(x, y));
  }
  EXPECT_GT(differing, 16 * 56 / 2);
}

// The light editor's map view: the selected point light's six cube faces, read from the shadow
// atlas by the ui pass (which so depends on this frame's shadow passes), under validation.
TEST_F(SandboxFrameTest, ThePanelsShowTheSelectedLightsShadowMap) {
  sandbox::Options options;
  options.ui = true;
  SceneView scene = load_scene_view(options.frame, float(width) / height);
  ecs::Entity point = ecs::null_entity;
  scene.scene.world.query<const scene::PointLight>().for_each(
      [&](ecs::Entity entity, const scene::PointLight&) { point = entity; });
  ASSERT_NE(point, ecs::null_entity);
  vk::FrameRing frames(context);
  sandbox::SandboxFrame frame(context, scene, options, frames.frames_in_flight());
  frame.frame().resize({width, height});
  frame.ui()->select(point);
  frame.ui()->show_map(true);
  for (int i = 0; i < 3; ++i) {
    frame.frame().record(frames.begin_frame(), i / 60.0);
    frames.submit();
  }
  frames.wait_idle();
  ASSERT_EQ(frame.ui()->depth_views().size(), 6u);
  for (const sandbox::UiDepthView& view : frame.ui()->depth_views()) EXPECT_TRUE(view.linear);
  EXPECT_EQ(executed_passes(*frame.frame().plan()).back(), "ui");
}

// The panels' "play": paused, the moving stress scene writes nothing, so every shadow map is kept.
// (With --threads 3: the frame's CPU work on three threads.)
TEST_F(SandboxFrameTest, PausedAnimationRedrawsNoShadowMap) {
  sandbox::Options options;
  options.frame.scene = "stress";
  options.frame.scene_params = {3000, 3, 3, 1.0f};
  options.ui = true;
  options.frame.renderer.cpu_threads = 3;
  SceneView scene = load_scene_view(options.frame, float(width) / height);
  vk::FrameRing frames(context);
  sandbox::SandboxFrame frame(context, scene, options, frames.frames_in_flight());
  EXPECT_EQ(frame.frame().renderer().workers().thread_count(), 3u);
  frame.frame().resize({width, height});
  ASSERT_TRUE(frame.ui()->playing());  // from --animate, on by default
  int at = 0;
  const auto views_drawn = [&] {
    frame.frame().record(frames.begin_frame(), at++ / 60.0);
    frames.submit();
    return frame.frame().renderer().shadow_stats().views_rendered;
  };
  views_drawn();
  EXPECT_GT(views_drawn(), 0u);  // every light moves
  frame.ui()->set_playing(false);
  views_drawn();
  EXPECT_EQ(views_drawn(), 0u);
  frame.ui()->set_playing(true);
  EXPECT_GT(views_drawn(), 0u);
  frames.wait_idle();
}

// ShadowSettings::update on lavapipe, under validation, with the stress scene's lights and crates
// moving: every_frame draws every map every frame, on_demand none until asked, then only that
// light's (its tiles pinned by --shadow-resolution requested, so no new tile redraws one).
TEST_F(SandboxFrameTest, UpdateModesDecideWhichMapsAreDrawnAgain) {
  sandbox::Options options;
  options.frame.scene = "stress";
  options.frame.scene_params = {3000, 3, 3, 1.0f};
  options.frame.renderer.shadow_resolution = shadows::ShadowResolution::requested;
  SceneView scene = load_scene_view(options.frame, float(width) / height);
  ecs::World& world = scene.scene.world;
  const auto set_update = [&](scene::ShadowUpdate update) {
    world.query<scene::ShadowSettings>().for_each(
        [&](ecs::Entity, scene::ShadowSettings& shadow) { shadow.update = update; });
  };
  ecs::Entity spot = ecs::null_entity;
  world.query<const scene::SpotLight>().for_each(
      [&](ecs::Entity entity, const scene::SpotLight&) { spot = entity; });
  ASSERT_NE(spot, ecs::null_entity);
  vk::FrameRing frames(context);
  sandbox::SandboxFrame frame(context, scene, options, frames.frames_in_flight());
  frame.frame().resize({width, height});
  int at = 0;
  const auto next_frame = [&] {
    frame.frame().record(frames.begin_frame(), at++ / 60.0);
    frames.submit();
    return frame.frame().renderer().shadow_stats();
  };
  set_update(scene::ShadowUpdate::every_frame);
  next_frame();
  for (int i = 0; i < 2; ++i) {
    const shadows::ShadowScheduleStats stats = next_frame();
    EXPECT_GT(stats.views_rendered, 0u);
    EXPECT_EQ(stats.views_cached, 0u) << "every map drawn every frame";
  }
  set_update(scene::ShadowUpdate::on_demand);
  for (int i = 0; i < 2; ++i) next_frame();  // the switch itself writes the settings
  for (int i = 0; i < 3; ++i) {
    const shadows::ShadowScheduleStats stats = next_frame();
    EXPECT_EQ(stats.views_rendered, 0u) << "lights and crates move, nothing asked";
    EXPECT_GT(stats.views_cached, 0u);
  }
  ASSERT_TRUE(scene::request_shadow_redraw(world, spot));
  EXPECT_EQ(next_frame().views_rendered, 1u) << "the spot light's map alone";
  EXPECT_EQ(next_frame().views_rendered, 0u);
  frames.wait_idle();
}

// --light-heatmap colors the tiles by how many lights light culling kept for them: the default
// scene's floor is lit everywhere, so most of the picture changes; every-light forward (--naive)
// has no tiles and so no heat map.
TEST_F(SandboxFrameTest, TheLightHeatMapColorsTheLitTiles) {
  const vk::Rgba8Image plain = render(sandbox::Options{}, 1);
  sandbox::Options heat;
  heat.light_heatmap = true;
  const vk::Rgba8Image colored = render(heat, 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "light heat map"), 1);
  EXPECT_GT(largest_difference(plain, colored), 40);
  heat.frame.naive = true;
  render(heat, 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "light heat map"), 0);
}

// --render-scale 0.5: the scene drawn at half the frame's size and scaled up into it, the
// overlays over it at full size. The picture stays the scene's, and the heat map colors the same
// places of the picture as at full size: its tiles are read at the scene's scale.
TEST_F(SandboxFrameTest, RenderScaleDrawsTheSceneSmallerUnderFullSizeOverlays) {
  sandbox::Options full;
  const vk::Rgba8Image plain = render(full, 1);
  full.light_heatmap = true;
  const vk::Rgba8Image heat = render(full, 1);
  EXPECT_EQ(scene_extent.width, width);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), upscale_pass_name), 0);

  sandbox::Options half = full;
  half.frame.render_scale = 0.5f;
  const vk::Rgba8Image half_heat = render(half, 1);
  EXPECT_EQ(scene_extent.width, width / 2);
  EXPECT_EQ(scene_extent.height, height / 2);
  ASSERT_EQ(half_heat.width, width) << "the frame keeps its size";
  const auto upscale = std::find(passes.begin(), passes.end(), upscale_pass_name);
  ASSERT_NE(upscale, passes.end());
  EXPECT_LT(upscale - passes.begin(),
            std::find(passes.begin(), passes.end(), "light heat map") - passes.begin());
  half.light_heatmap = false;
  const vk::Rgba8Image half_plain = render(half, 1);
  EXPECT_LT(share_differing(plain, half_plain, 48), 0.05) << "the same scene, softer";

  const std::vector<bool> at_full = changed_pixels(plain, heat);
  const std::vector<bool> at_half = changed_pixels(half_plain, half_heat);
  size_t agree = 0, colored = 0;
  for (size_t i = 0; i < at_full.size(); ++i) {
    agree += at_full[i] == at_half[i];
    colored += at_half[i];
  }
  EXPECT_GT(colored, at_full.size() / 4);
  // 83% at this size, where a tile of the half-size scene is 32 pixels of the frame; reading the
  // tiles at the frame's scale agrees on 25%.
  EXPECT_GT(double(agree) / double(at_full.size()), 0.7);
}

TEST_F(SandboxFrameTest, DepthOverlayDrawsOnlyIntoTheBottomRightQuarter) {
  sandbox::Options plain;
  sandbox::Options overlaid;
  overlaid.depth_overlay = true;
  const vk::Rgba8Image without = render(plain, 2);
  const vk::Rgba8Image with = render(overlaid, 2);
  ASSERT_GE(passes.size(), 2u);
  EXPECT_EQ(passes[passes.size() - 2], "tone map");
  EXPECT_EQ(passes.back(), "depth overlay");

  int changed_inside = 0, changed_outside = 0, grey_inside = 0, inside = 0;
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const uint8_t* a = without.at(x, y);
      const uint8_t* b = with.at(x, y);
      const bool changed = !std::equal(a, a + 3, b);
      if (x >= width / 2 && y >= height / 2) {
        ++inside;
        changed_inside += changed;
        grey_inside += b[0] == b[1] && b[1] == b[2];
      } else {
        changed_outside += changed;
      }
    }
  }
  EXPECT_EQ(changed_outside, 0);
  EXPECT_EQ(grey_inside, inside) << "the overlay shows depth as grey";
  EXPECT_GT(changed_inside, inside / 2);
}

}  // namespace
}  // namespace sg::test
