// SPDX-License-Identifier: MIT
// The engine's frame on lavapipe with validation and synchronization validation on (GpuTest
// fails on any report): the built-in scenes, every lighting and shadow-view path against the
// others, and the passes the plan runs.
#include <algorithm>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "systems/frame/frame.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/headless_frames.h"
#include "systems/gpu/camera.h"
#include "systems/lighting/light_tiles_pass.h"
#include "systems/lighting/tiled_lighting_pass.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"
#include "tests/support/frame_checks.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 128;
constexpr uint32_t height = 96;

class FrameTest : public GpuTest {
 protected:
  // Renders `frame_count` frames of `settings`' scene and returns the last picture; with
  // `before_last`, calls it before the last frame.
  vk::Rgba8Image render(const FrameSettings& options, uint32_t frame_count,
                        const std::function<void(Frame&)>& before_last = {}) {
    SceneView scene = load_scene_view(options, float(width) / height);
    vk::FrameRing frames(context);
    Frame frame(context, scene, options, frames.frames_in_flight());
    frame.resize({width, height});
    GpuTimeLog gpu_times;
    if (before_last) {
      render_headless_frames(frame, frames, frame_count - 1, gpu_times);
      before_last(frame);
      render_headless_frames(frame, frames, 1, gpu_times, false, frame_count - 1);
    } else {
      render_headless_frames(frame, frames, frame_count, gpu_times);
    }
    passes = executed_passes(*frame.plan());
    shadow_stats = frame.renderer().shadow_stats();
    dropped_light_pairs = frame.take_dropped_light_pairs();
    map_timeline = frame.map_timeline();
    first_maps = frame.first_maps();
    return vk::read_rgba8(context, frame.image());
  }

  std::vector<std::string> passes;
  shadows::ShadowScheduleStats shadow_stats;  // the last frame's
  uint64_t dropped_light_pairs = 0;           // over the frames rendered
  Frame::MapTimeline map_timeline;
  std::optional<uint64_t> first_maps;  // Frame::first_maps
};

// Every shadow view due in a frame: culled, sorted into draws and drawn by these passes.
const std::vector<std::string> batched_shadow_passes{"shadow cull reset", "shadow cull", "shadow draws",
                                                     "shadow scatter", "shadow views"};

std::vector<std::string> followed_by(std::vector<std::string> passes, const std::vector<std::string>& more) {
  passes.insert(passes.end(), more.begin(), more.end());
  return passes;
}

// The stress scene with `triangles`, `points` point and `spots` spot lights, `moving` of them
// moving.
FrameSettings stress(uint64_t triangles, uint32_t points, uint32_t spots, float moving) {
  FrameSettings options;
  options.scene = "stress";
  options.scene_params.triangles = triangles;
  options.scene_params.point_lights = points;
  options.scene_params.spot_lights = spots;
  options.scene_params.moving_fraction = moving;
  return options;
}

// A 20 x 20 floor whose top is at y = 0, and a square plate 0.1 thick and `plate_side` wide
// centred at `plate_centre`, both of `material`.
void add_floor_and_plate(scene::Scene& scene, const scene::Material& material, glm::vec3 plate_centre,
                         float plate_side) {
  const uint32_t box = scene::add_box_mesh(scene.meshes);
  scene::add_instance(scene, box, {{0.0f, -0.5f, 0.0f}, glm::quat(1, 0, 0, 0), {20.0f, 1.0f, 20.0f}},
                      material);
  scene::add_instance(scene, box, {plate_centre, glm::quat(1, 0, 0, 0), {plate_side, 0.1f, plate_side}},
                      material);
}

FrameSettings lit_by(LightingPath lighting) {
  FrameSettings options;
  options.renderer.lighting = lighting;
  return options;
}

// Deferred lighting against a forward path: the same formulas, but the G-buffer has 16-bit
// normals and 8-bit base colors, and deferred takes positions back from the depth buffer, a
// hair from the rasterizer's: a pixel on a shadow's very edge may fall on the other side.
void expect_same_but_edges(const vk::Rgba8Image& forward, const vk::Rgba8Image& deferred) {
  EXPECT_LE(share_differing(forward, deferred, 2), 0.001) << "pixels more than 2 levels of 255 apart";
}

TEST_F(FrameTest, DefaultSceneRendersThroughTheGraph) {
  const std::vector<std::string> lighting{"g-buffer",
                                          "light tiles reset",
                                          "light tiles",
                                          "lighting 2d hard",
                                          "lighting 2d pcf",
                                          "lighting 2d noise",
                                          "lighting 2d pcss_noise",
                                          "lighting cube hard",
                                          "lighting cube pcss",
                                          "tone map"};
  // The first frame draws every shadow view (lavapipe has shaderOutputLayer, so they are
  // batched), then the G-buffer (which on a CPU device starts the lit sum with the ambient term),
  // light culling, one lighting pass per light group the scene uses (its six lights use six of
  // the eleven), tone mapping.
  render(lit_by(LightingPath::deferred), 1);
  EXPECT_EQ(passes, followed_by(batched_shadow_passes, lighting));
  // Nothing moves in the default scene: later frames keep every map.
  const vk::Rgba8Image image = render(lit_by(LightingPath::deferred), 3);
  EXPECT_EQ(passes, lighting);
  // Something was drawn: the picture is not a single color.
  const uint8_t* first = image.at(0, 0);
  bool varied = false;
  for (uint32_t y = 0; y < height && !varied; ++y) {
    for (uint32_t x = 0; x < width && !varied; ++x) varied = !std::equal(first, first + 3, image.at(x, y));
  }
  EXPECT_TRUE(varied);
}

TEST_F(FrameTest, MovingStressSceneStaysCleanAcrossFrames) {
  FrameSettings options = stress(3000, 3, 3, 0.5f);
  options.renderer.lighting = LightingPath::fused;
  render(options, 4);
  // Moving lights redraw their maps every frame.
  EXPECT_EQ(passes, followed_by(batched_shadow_passes, {"depth prepass", "fused forward"}));
  options.renderer.lighting = LightingPath::deferred;
  render(options, 4);
  EXPECT_EQ(passes.back(), "tone map");
}

// Every lighting path lights the same surfaces with the same formulas (the forward paths with the
// same positions, so they agree everywhere), and the noise algorithms draw their numbers per
// pixel, so every path draws the same.
TEST_F(FrameTest, EveryLightingPathRendersTheSamePicture) {
  const vk::Rgba8Image forward = render(lit_by(LightingPath::every_light), 2);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "forward"), 1);
  const vk::Rgba8Image deferred = render(lit_by(LightingPath::deferred), 2);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "g-buffer"), 1);
  expect_same_but_edges(forward, deferred);

  // The naive baseline: a pass per view and six per cube, every map every frame, every caster in
  // every view, every light at every pixel.
  FrameSettings naive;
  naive.naive = true;
  const vk::Rgba8Image baseline = render(naive, 2);
  EXPECT_EQ(std::count_if(passes.begin(), passes.end(),
                          [](const std::string& name) { return name.find(" face ") != std::string::npos; }),
            12);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "light tiles"), 0);
  EXPECT_LE(largest_difference(baseline, forward), 2) << "levels of 255 in the worst channel";
  expect_same_but_edges(baseline, deferred);

  // Every light at every pixel again, tone mapped in the same pass.
  const vk::Rgba8Image fused = render(lit_by(LightingPath::fused), 2);
  EXPECT_EQ(passes.back(), "fused forward");
  EXPECT_LE(largest_difference(fused, forward), 2);
}

// Passes added after the lighting (tools' depth capture, overlays) read the camera's depth as the
// lighting left it: every path hands on its newest version, and the depths agree.
TEST_F(FrameTest, EveryLightingPathHandsTheCameraDepthToLaterPasses) {
  std::vector<std::vector<float>> depths;
  for (const LightingPath lighting :
       {LightingPath::every_light, LightingPath::deferred, LightingPath::fused}) {
    FrameSettings options = lit_by(lighting);
    SceneView scene = load_scene_view(options, float(width) / height);
    vk::FrameRing frames(context);
    Frame frame(context, scene, options, frames.frames_in_flight());
    frame.resize({width, height});
    frame.capture_depth();
    frame.record(frames.begin_frame(), 0.0);
    frames.submit();
    frames.wait_idle();
    depths.push_back(frame.read_captured_depth().depths);
  }
  const std::vector<float>& forward = depths.front();
  EXPECT_GT(std::count_if(forward.begin(), forward.end(), [](float d) { return d > camera_far_depth; }),
            long(forward.size() / 2))
      << "the scene fills most of the picture";
  for (size_t path = 1; path < depths.size(); ++path) EXPECT_EQ(depths[path], forward) << "path " << path;
}

// A group with one light shades from its record alone (SINGLE_LIGHT, GROUPS_SINGLE), a group with
// several from each tile's list or, fused, from the records up to the next group's: with every
// light on pcf, the stress scene's three point lights share one group and its three spots and the
// sun another, and deferred and fused lighting still draw what forward lighting of every light
// draws.
TEST_F(FrameTest, GroupsOfManyLightsMatchForward) {
  FrameSettings options = stress(3000, 3, 3, 0.0f);
  options.algorithm = scene::ShadowAlgorithm::pcf;
  options.renderer.lighting = LightingPath::every_light;
  const vk::Rgba8Image forward = render(options, 2);
  options.renderer.lighting = LightingPath::deferred;
  const vk::Rgba8Image deferred = render(options, 2);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "lighting 2d pcf"), 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "lighting cube pcf"), 1);
  expect_same_but_edges(forward, deferred);
  options.renderer.lighting = LightingPath::fused;
  const vk::Rgba8Image fused = render(options, 2);
  EXPECT_EQ(passes.back(), "fused forward");
  EXPECT_LE(largest_difference(fused, forward), 2) << "levels of 255 in the worst channel";
}

// Group sets (TiledLightingPass): from the third frame, which reads what the first counted, tiles
// where the default scene's lights overlap take one pass for their groups; the picture is the one
// a pass per group draws, to the 16-bit lit sum's rounding. Built in the background (the
// default), a set's pipeline is asked for once the set has been picked
// frames_before_background_build frames in a row, the frames going on without it; once built, a
// frame takes it and draws what a run that builds it in the frame draws.
TEST_F(FrameTest, GroupSetsDrawWhatAPassPerGroupDraws) {
  constexpr uint32_t frame_count = TiledLightingPass::frames_before_background_build + 4;
  FrameSettings options = lit_by(LightingPath::deferred);
  options.renderer.group_sets = false;
  const vk::Rgba8Image per_group = render(options, frame_count);
  EXPECT_EQ(std::count_if(passes.begin(), passes.end(),
                          [](const std::string& name) { return name.find(" + ") != std::string::npos; }),
            0);
  options.renderer.group_sets = true;
  options.renderer.pipeline_builds = PipelineBuilds::in_frame;
  const vk::Rgba8Image with_sets = render(options, frame_count);
  const std::vector<std::string> in_frame_passes = passes;
  const auto sets = std::count_if(passes.begin(), passes.end(), [](const std::string& name) {
    return name.starts_with("lighting ") && name.find(" + ") != std::string::npos;
  });
  EXPECT_GE(sets, 2) << "the sun's group with others, in the most common combinations";
  EXPECT_LE(sets, long(tiles::LIGHT_GROUP_SETS));
  // A set sums its groups before the lit sum's 16 bits round, a pass per group after each: a
  // level of rounding in a few percent of the channels.
  EXPECT_LE(largest_difference(per_group, with_sets), 1) << "levels of 255 in the worst channel";
  EXPECT_LT(share_differing(per_group, with_sets, 0), 0.1);

  options.renderer.pipeline_builds = PipelineBuilds::background;
  const vk::Rgba8Image background =
      render(options, frame_count, [](Frame& frame) { frame.renderer().wait_for_pipeline_builds(); });
  EXPECT_EQ(passes, in_frame_passes);
  EXPECT_EQ(background.pixels, with_sets.pixels);
}

// Deferred lighting's lit sum started by a pass of its own or by the G-buffer: the same shading
// code over the same tiles, so the same picture to rounding (the 16-bit sum, and the G-buffer's
// ambient term takes the base color before its 8-bit storage).
TEST_F(FrameTest, DeferredLightingStartedByTheGBufferMatchesItsOwnPass) {
  FrameSettings options = lit_by(LightingPath::deferred);
  options.renderer.lit_sum_start = LitSumStart::pass;
  const vk::Rgba8Image own_pass = render(options, 2);
  const std::vector<std::string> own_pass_passes = passes;
  options.renderer.lit_sum_start = LitSumStart::gbuffer;
  const vk::Rgba8Image from_gbuffer = render(options, 2);
  std::vector<std::string> with_ambient_pass = passes;
  with_ambient_pass.insert(std::find(with_ambient_pass.begin(), with_ambient_pass.end(), "lighting 2d hard"),
                           "lighting ambient");
  EXPECT_EQ(own_pass_passes, with_ambient_pass);
  EXPECT_LE(largest_difference(own_pass, from_gbuffer), 1) << "levels of 255 in the worst channel";
  EXPECT_LT(share_differing(own_pass, from_gbuffer, 0), 0.05);
}

// automatic on a CPU device, each frame: the fused forward pass for up to four lights (fewest
// full-screen passes) and a few thousand triangles, deferred for more; the default scene has six
// lights, spot-columns one light and 53.7k triangles.
TEST_F(FrameTest, AutomaticLightingFusesAFewLightsOnACpuDevice) {
  render(FrameSettings{}, 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "g-buffer"), 1);
  FrameSettings four_lights = stress(3000, 2, 1, 0.0f);  // two point lights, a spot light and the sun
  render(four_lights, 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "fused forward"), 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "tone map"), 0);
  FrameSettings five_lights = stress(3000, 2, 2, 0.0f);
  render(five_lights, 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "g-buffer"), 1);
  FrameSettings heavy_geometry;
  heavy_geometry.scene = "spot-columns";
  render(heavy_geometry, 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "g-buffer"), 1);
}

// A window on a CPU device draws the scene at half its size unless told otherwise; headless
// frames and GPUs at full size.
TEST_F(FrameTest, RenderScaleIsHalfOnlyInACpuDevicesWindowByDefault) {
  ASSERT_EQ(context.properties().deviceType, VK_PHYSICAL_DEVICE_TYPE_CPU);
  FrameSettings settings;
  EXPECT_EQ(render_scale_for(settings.render_scale, context, true), 0.5f);
  EXPECT_EQ(render_scale_for(settings.render_scale, context, false), 1.0f);
  settings.render_scale = 0.75f;
  EXPECT_EQ(render_scale_for(settings.render_scale, context, true), 0.75f);
  EXPECT_EQ(render_scale_for(settings.render_scale, context, false), 0.75f);
}

// The scene's extent is the frame's times the scale, rounded, at least a pixel; scales outside
// (0, 1] are refused.
TEST_F(FrameTest, TheSceneExtentFollowsTheRenderScale) {
  SceneView scene = load_scene_view(FrameSettings{}, 1.0f);
  Frame frame(context, scene, FrameSettings{}, 2);
  frame.resize({101, 51}, 0.5f);
  EXPECT_EQ(frame.image().extent().width, 101u);
  EXPECT_EQ(frame.scene_extent().width, 51u);
  EXPECT_EQ(frame.scene_extent().height, 26u);
  frame.resize({3, 1}, 0.25f);
  EXPECT_EQ(frame.scene_extent().width, 1u);
  EXPECT_EQ(frame.scene_extent().height, 1u);
  frame.resize({64, 64});
  EXPECT_EQ(frame.scene_extent().width, 64u);
  EXPECT_THROW(frame.resize({64, 64}, 0.0f), std::invalid_argument);
  EXPECT_THROW(frame.resize({64, 64}, 1.5f), std::invalid_argument);
}

// The shadow-only view: white surfaces under white light, so every pixel is grey but the
// background (the clear color, as in the top-left corner), on every lighting path alike, and
// unlike the lit picture.
TEST_F(FrameTest, TheShadowOnlyViewIsGreyOnEveryLightingPath) {
  const auto grey_fraction = [](const vk::Rgba8Image& image) {
    size_t grey = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
      const int r = image.pixels[i], g = image.pixels[i + 1], b = image.pixels[i + 2];
      grey += (std::abs(r - g) <= 1 && std::abs(g - b) <= 1) ||
              std::equal(&image.pixels[i], &image.pixels[i + 3], image.at(0, 0));
    }
    return double(grey) / double(image.pixels.size() / 4);
  };
  const vk::Rgba8Image lit = render(lit_by(LightingPath::deferred), 1);
  std::vector<vk::Rgba8Image> views;
  for (const LightingPath path : {LightingPath::deferred, LightingPath::every_light, LightingPath::fused}) {
    FrameSettings options = lit_by(path);
    options.renderer.view = LightingView::shadows;
    views.push_back(render(options, 1));
  }
  EXPECT_EQ(grey_fraction(views[0]), 1.0);
  EXPECT_LT(grey_fraction(lit), 0.5);
  expect_same_but_edges(views[1], views[0]);
  EXPECT_LE(largest_difference(views[1], views[2]), 2);
}

TEST_F(FrameTest, SixPassCubesRenderTheSamePictureAsLayeredCubes) {
  FrameSettings layered;
  layered.renderer.shadow_views = shadows::ShadowViewPath::per_light;
  FrameSettings six = layered;
  six.renderer.cube_shadows = shadows::CubeShadowMode::six_passes;
  const vk::Rgba8Image a = render(layered, 1);
  const vk::Rgba8Image b = render(six, 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "shadow warm point face 3"), 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "shadow warm point face 0") +
                std::count(passes.begin(), passes.end(), "shadow cool point face 5"),
            2);
  // The sun's cascades are a pass each, as many as the view uses.
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "shadow sun cascade 2"), 1);
  EXPECT_EQ(std::count_if(passes.begin(), passes.end(),
                          [](const std::string& name) {
                            return name.starts_with("shadow") && !name.starts_with("shadow sun cascade");
                          }),
            3 + 2 * 6);
  int differing = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) differing += std::abs(int(a.pixels[i]) - int(b.pixels[i])) > 1;
  EXPECT_EQ(differing, 0);
}

// The GPU-driven batch draws each view into its tile by moving clip space; the per-light passes
// set a viewport on the tile. Both rasterize the same triangles into the same texels.
TEST_F(FrameTest, BatchedShadowViewsRenderTheSamePictureAsPerLightPasses) {
  FrameSettings per_light;
  per_light.renderer.shadow_views = shadows::ShadowViewPath::per_light;
  const vk::Rgba8Image a = render(per_light, 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "shadow warm point"), 1);
  const vk::Rgba8Image b = render(FrameSettings{}, 1);
  EXPECT_EQ(std::count(passes.begin(), passes.end(), "shadow views"), 1);
  EXPECT_LE(largest_difference(a, b), 1);
}

// The same in the stress hall, whose 176 casters make three of the cull's blocks (CASTER_BLOCK),
// lights and crates moving; the compute raster keeps static layers, so views are also drawn with
// the moving casters alone, a list with blocks of its own. The blocks a view does not meet hold
// no caster it draws. In this hall no pixel's shadow hangs on a texel centre at a triangle's edge,
// where the two rasters may differ (docs/ALGORITHMS.md, 3.1).
TEST_F(FrameTest, BatchedShadowViewsOfManyCastersRenderTheSamePictureAsPerLightPasses) {
  FrameSettings per_light = stress(3000, 3, 3, 0.5f);
  per_light.renderer.shadow_views = shadows::ShadowViewPath::per_light;
  const vk::Rgba8Image a = render(per_light, 3);
  for (const shadows::ShadowRaster raster :
       {shadows::ShadowRaster::hardware, shadows::ShadowRaster::compute}) {
    SCOPED_TRACE(raster == shadows::ShadowRaster::compute ? "compute raster" : "hardware raster");
    FrameSettings batched = stress(3000, 3, 3, 0.5f);
    batched.renderer.shadow_raster = raster;
    const vk::Rgba8Image b = render(batched, 3);
    EXPECT_EQ(std::count(passes.begin(), passes.end(), "shadow cull"), 1);
    EXPECT_LE(largest_difference(a, b), 1);
  }
}

// A frame whose maps were all kept from earlier frames shows what drawing them again shows.
TEST_F(FrameTest, CachedShadowsArePixelIdenticalToShadowsDrawnFromScratch) {
  for (const shadows::ShadowViewPath views :
       {shadows::ShadowViewPath::batched, shadows::ShadowViewPath::per_light}) {
    FrameSettings cached;
    cached.renderer.shadow_views = views;
    const vk::Rgba8Image kept = render(cached, 3);
    EXPECT_EQ(std::count_if(passes.begin(), passes.end(),
                            [](const std::string& name) { return name.starts_with("shadow"); }),
              0)
        << "the third frame draws no shadow view";
    FrameSettings fresh = cached;
    fresh.renderer.cache_shadows = false;
    const vk::Rgba8Image drawn = render(fresh, 3);
    EXPECT_GT(std::count_if(passes.begin(), passes.end(),
                            [](const std::string& name) { return name.starts_with("shadow"); }),
              0);
    EXPECT_EQ(kept.pixels, drawn.pixels);
  }
}

// Issue 11's limit case: 400 point lights (2,400 cube faces, past the 2,048 layers a cube array
// could hold) and 2,100 spot lights, tiny maps in a small window, clean under validation and
// synchronization validation; the lights beyond the budget lose resolution, then their shadow.
TEST_F(FrameTest, ThousandsOfShadowedLightsStayWithinDeviceLimits) {
  FrameSettings options = stress(2000, 400, 2100, 0.0f);
  options.renderer.shadow_memory_mib = 16;  // one page of 2048 x 2048
  render(options, 2);
  EXPECT_EQ(passes.back(), "tone map");
  // The first frame drew as many views as the per-frame budget allows, the second the rest.
  constexpr uint32_t views = 2100 + 1 + 400 * 6;  // spots, the sun, cube faces
  EXPECT_EQ(shadow_stats.views_rendered + shadow_stats.views_cached, views);
  EXPECT_EQ(shadow_stats.views_cached, shadows::default_shadow_view_budget);
  EXPECT_EQ(shadow_stats.lights_waiting, 0u);
  // So every light had a map from the second frame on, not the first.
  EXPECT_EQ(first_maps, std::optional<uint64_t>(1));
  // The budget holds 2048^2 texels: most lights got the smallest tiles.
  EXPECT_EQ(shadow_stats.pages_used, 1u);
  ASSERT_FALSE(shadow_stats.lights_per_resolution.empty());
  EXPECT_EQ(shadow_stats.lights_per_resolution.front().first, shadows::min_shadow_resolution);
  EXPECT_GT(shadow_stats.lights_per_resolution.front().second, 1000u);
}

// Dozens of lights over every tile, lit from tile lists, against the naive frame that lights
// every pixel by every light: the lists leave no light out (lists of at most 8 darken 13% of the
// pixels), dimmed so that no sum saturates and hides a missing light.
TEST_F(FrameTest, DenseLightsFromTileListsMatchTheNaiveFrame) {
  FrameSettings options = stress(2000, 150, 150, 0.0f);
  options.scene_params.light_spread = 0.3f;
  options.camera_name = "street";  // at eye height, looking across the lights
  options.renderer.lighting = LightingPath::deferred;
  options.renderer.exposure = 0.25f;
  const vk::Rgba8Image tiled = render(options, 2);
  EXPECT_NE(std::find(passes.begin(), passes.end(), "light tiles"), passes.end());
  EXPECT_EQ(dropped_light_pairs, 0u);
  options.naive = true;
  const vk::Rgba8Image naive = render(options, 2);
  int brightest = 0;
  for (size_t i = 0; i < naive.pixels.size(); i += 4) {
    brightest =
        std::max({brightest, int(naive.pixels[i]), int(naive.pixels[i + 1]), int(naive.pixels[i + 2])});
  }
  EXPECT_LT(brightest, 250) << "a saturated sum would hide a missing light";
  EXPECT_GT(brightest, 40) << "too dim to tell";
  EXPECT_LE(share_differing(tiled, naive, 2), 0.001) << "pixels more than 2 levels of 255 apart";
}

// Moving lights under a short view budget wait their turn, and the frame says for how long: 40
// moving spot lights, 8 views a frame, so each map is redrawn about every 5 frames (the sun takes
// a turn too) and, stalest first, none waits much longer. With every due view drawn, none lags.
TEST_F(FrameTest, MapsOfMovingLightsLagUnderAShortViewBudget) {
  FrameSettings options = stress(2000, 0, 40, 1.0f);
  options.renderer.shadow_view_budget = 8;
  render(options, 12);
  ASSERT_EQ(map_timeline.lag_max.size(), 12u);
  EXPECT_GE(map_timeline.lag_max.back(), 4.0);
  EXPECT_LE(map_timeline.lag_max.back(), 8.0);
  EXPECT_GE(map_timeline.lag_p50.back(), 1.0);
  options.renderer.shadow_view_budget = 0;
  render(options, 4);
  EXPECT_EQ(map_timeline.lag_max.back(), 0.0);
}

// The Frame panel's budgets while running (SceneRenderer::set_shadow_budgets): 40 moving spot
// lights are due every frame; 3 views a frame then draw 3, and no cap draws them all again.
TEST_F(FrameTest, ShadowBudgetsChangeWhileRunning) {
  const FrameSettings options = stress(2000, 0, 40, 1.0f);
  SceneView scene = load_scene_view(options, float(width) / height);
  vk::FrameRing frames(context);
  Frame frame(context, scene, options, frames.frames_in_flight());
  frame.resize({width, height});
  GpuTimeLog gpu_times;
  const auto views_drawn = [&](uint32_t view_budget, double time_budget_ms) {
    frame.renderer().set_shadow_budgets(view_budget, time_budget_ms);
    render_headless_frames(frame, frames, 2, gpu_times);
    return frame.renderer().shadow_stats().views_rendered;
  };
  EXPECT_EQ(views_drawn(0, 0.0), 41u) << "every moving spot light and the sun";
  EXPECT_EQ(views_drawn(3, 0.0), 3u);
  EXPECT_EQ(frame.renderer().shadow_view_budget(), 3u);
  EXPECT_EQ(views_drawn(0, 2.5), 41u);
  EXPECT_EQ(frame.renderer().shadow_time_budget_ms(), 2.5);
}

// Ranked filtering (--filtered-shadows): at each pixel only the N lights adding most run their
// filter kernels. Where no pixel has more filtering lights than N (the default scene has four),
// the picture is that of every light filtering; with N = 1 the lighter lights' penumbrae turn
// hard, which changes pixels: the floor pass ranks, and the groups read its floor.
TEST_F(FrameTest, RankedFilteringKeepsThePictureWhereFewLightsFilter) {
  FrameSettings options = lit_by(LightingPath::deferred);
  options.renderer.filtered_lights = 0;
  const vk::Rgba8Image every_light = render(options, 2);
  EXPECT_EQ(std::find(passes.begin(), passes.end(), "lighting filter floor"), passes.end());
  options.renderer.filtered_lights = 8;
  const vk::Rgba8Image ranked = render(options, 2);
  EXPECT_NE(std::find(passes.begin(), passes.end(), "lighting filter floor"), passes.end());
  EXPECT_EQ(share_differing(every_light, ranked, 1), 0.0) << "pixels more than 1 level of 255 apart";
  options.renderer.filtered_lights = 1;
  EXPECT_GT(share_differing(every_light, render(options, 2), 2), 0.001) << "one filtering light a pixel";
}

// Where many lights overlap (the dense frame of the test above, 300 lights), ranking at 8 a pixel
// changes only the penumbrae of the lights that add least: within 2 levels of every light
// filtering on all but 5% of the pixels, within 10 on all but 0.5%. Measured on lavapipe
// (2026-12-02) at 480x270: 2.3% and 0.11%.
TEST_F(FrameTest, RankedFilteringChangesLittleWhereManyLightsOverlap) {
  FrameSettings options = stress(2000, 150, 150, 0.0f);
  options.scene_params.light_spread = 0.3f;
  options.camera_name = "street";
  options.renderer.lighting = LightingPath::deferred;
  options.renderer.exposure = 0.25f;
  options.renderer.filtered_lights = 0;
  const vk::Rgba8Image every_light = render(options, 2);
  options.renderer.filtered_lights = 8;
  const vk::Rgba8Image ranked = render(options, 2);
  EXPECT_LE(share_differing(every_light, ranked, 2), 0.05);
  EXPECT_LE(share_differing(every_light, ranked, 10), 0.005);
  EXPECT_GT(share_differing(every_light, ranked, 0), 0.0) << "no light was ranked out of its filter";
}

// Ranking weighs a light's highlight as well as its diffuse light: on a black glossy floor, lit
// only through its specular term, one filtering light a pixel changes the penumbrae of the others,
// and that one keeps its own. Weights bounded without the specular term (the cheap bound that
// spares most lights the exact weight) would put the floor at zero there, every light
// filtering, or keep every light below it, none filtering.
TEST_F(FrameTest, RankedFilteringWeighsHighlights) {
  const auto render_glossy = [&](uint32_t filtered_lights, scene::ShadowAlgorithm algorithm) {
    SceneView scene;
    scene.scene.name = "glossy floor";
    scene::Material glossy;
    glossy.base_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    glossy.specular = 1.0f;
    glossy.shininess = 2.0f;
    add_floor_and_plate(scene.scene, glossy, {0.0f, 1.5f, 0.0f}, 1.5f);
    scene::ShadowSettings soft;
    soft.algorithm = algorithm;
    soft.resolution = 64;
    soft.pcf_radius = 3.0f;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 at{1.5f * float(k - 1), 4.0f, -1.0f};
      scene::SpotLight spot;
      spot.range = 30.0f;
      spot.outer_cone = glm::radians(60.0f);
      scene::add_light(scene.scene, spot, {at, scene::look_rotation(at, {0.0f, 0.0f, 0.0f}), glm::vec3(1.0f)},
                       soft, "spot " + std::to_string(k));
    }
    ecs::update_world_transforms(scene.scene.world, 0);
    // Looking at the floor against the lights, where their highlights lie.
    scene.pose = {{0.0f, 3.0f, 5.0f}, {0.0f, 0.0f, -0.5f}};
    FrameSettings options = lit_by(LightingPath::deferred);
    options.renderer.filtered_lights = filtered_lights;
    vk::FrameRing frames(context);
    Frame frame(context, scene, options, frames.frames_in_flight());
    frame.resize({width, height});
    GpuTimeLog gpu_times;
    render_headless_frames(frame, frames, 2, gpu_times);
    return vk::read_rgba8(context, frame.image());
  };
  const vk::Rgba8Image one_filtering = render_glossy(1, scene::ShadowAlgorithm::pcf);
  EXPECT_GT(share_differing(render_glossy(0, scene::ShadowAlgorithm::pcf), one_filtering, 2), 0.001)
      << "every light filtering";
  EXPECT_GT(share_differing(render_glossy(0, scene::ShadowAlgorithm::hard), one_filtering, 2), 0.001)
      << "no light filtering";
}

// A spot light's shadow color fades out with the light at its cone's rim: a plate shadows the
// whole cone on a white floor, and the floor's red, the shadow color, runs from full under the
// light's axis down to the background's near the rim (ALGORITHMS.md 2.5), where a shadow color
// that ignored the cone drew a hard red edge.
TEST_F(FrameTest, ShadowColorFadesOutAtTheSpotConesRim) {
  SceneView scene;
  scene.scene.name = "tinted shadow";
  scene::Material white;
  white.base_color = glm::vec4(1.0f);
  white.specular = 0.0f;
  add_floor_and_plate(scene.scene, white, {0.0f, 2.5f, 0.0f}, 8.0f);
  scene::ShadowSettings tinted;
  tinted.algorithm = scene::ShadowAlgorithm::hard;
  tinted.shadow_color = {1.0f, 0.0f, 0.0f};
  scene::SpotLight spot;
  spot.range = 50.0f;
  spot.inner_cone = glm::radians(25.0f);
  spot.outer_cone = glm::radians(30.0f);  // the rim 5 tan 30 = 2.89 from the axis on the floor
  scene::add_light(
      scene.scene, spot,
      {glm::vec3(0.0f, 5.0f, 0.0f), scene::look_rotation({0, 5, 0}, {0, 0, 0.01f}), glm::vec3(1.0f)}, tinted,
      "spot");
  ecs::update_world_transforms(scene.scene.world, 0);
  // Under the plate, looking down with a wide lens that sees past the rim.
  scene.pose = {{0.0f, 1.0f, 0.01f}, {0.0f, 0.0f, 0.0f}};
  scene.lens.yfov = glm::radians(150.0f);
  FrameSettings options;
  options.renderer.exposure = 0.5f;
  vk::FrameRing frames(context);
  Frame frame(context, scene, options, frames.frames_in_flight());
  frame.resize({width, height});
  GpuTimeLog gpu_times;
  render_headless_frames(frame, frames, 2, gpu_times);
  const vk::Rgba8Image image = vk::read_rgba8(context, frame.image());
  const glm::mat4 view_projection =
      projection_matrix(scene.lens, float(width) / height) * view_matrix(scene.pose);
  const auto red_at = [&](float x) {  // the floor's red channel at (x, 0, 0)
    const glm::vec4 clip = view_projection * glm::vec4(x, 0.0f, 0.0f, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const uint8_t* p =
        image.at(uint32_t((ndc.x * 0.5f + 0.5f) * width), uint32_t((ndc.y * 0.5f + 0.5f) * height));
    EXPECT_EQ(p[1], p[2]) << "the floor is grey but for the shadow color, at x " << x;
    return int(p[0]) - int(p[1]);
  };
  const int centre = red_at(0.0f);
  const int near_rim = red_at(2.8f);  // cone factor 0.16 there
  const int outside = red_at(3.2f);
  EXPECT_GT(centre, 60) << "the shadow color under the light";
  EXPECT_LE(outside, 1) << "no shadow color outside the cone";
  EXPECT_LT(near_rim, centre / 3) << "the shadow color near the rim, where the light has nearly faded";
}

// A material's base-color texture multiplies its base color: a white floor with a green
// texture renders green, the same floor without it grey.
TEST_F(FrameTest, MaterialTexturesTintTheBaseColor) {
  const auto floor_pixel = [&](bool textured) {
    SceneView scene;
    scene.scene.name = "textured floor";
    const uint32_t box = scene::add_box_mesh(scene.scene.meshes);
    scene.scene.textures.textures.push_back({"green", 2, 2, std::vector<uint8_t>(16, 0)});
    for (size_t texel = 0; texel < 4; ++texel) {
      scene.scene.textures.textures[0].pixels[texel * 4 + 1] = 255;
      scene.scene.textures.textures[0].pixels[texel * 4 + 3] = 255;
    }
    scene::Material white;
    white.base_color = glm::vec4(1.0f);
    white.specular = 0.0f;
    if (textured) white.base_color_texture = 0;
    scene::add_instance(scene.scene, box, {{0.0f, -0.5f, 0.0f}, glm::quat(1, 0, 0, 0), {20.0f, 1.0f, 20.0f}},
                        white);
    scene::add_light(
        scene.scene, scene::DirectionalLight{glm::vec3(1.0f), 0.5f},
        {glm::vec3(0.0f, 5.0f, 0.0f), scene::look_rotation({0, 5, 0}, {0.1f, 0, 0}), glm::vec3(1.0f)},
        scene::ShadowSettings{}, "sun");
    ecs::update_world_transforms(scene.scene.world, 0);
    scene.pose = {{0.0f, 6.0f, 0.1f}, {0.0f, 0.0f, 0.0f}};
    vk::FrameRing frames(context);
    Frame frame(context, scene, FrameSettings{}, frames.frames_in_flight());
    frame.resize({width, height});
    frame.record(frames.begin_frame(), 0.0);
    frames.submit();
    frames.wait_idle();
    const vk::Rgba8Image image = vk::read_rgba8(context, frame.image());
    const uint8_t* p = image.at(width / 2, height / 2);
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  const std::array<int, 3> green = floor_pixel(true);
  const std::array<int, 3> grey = floor_pixel(false);
  EXPECT_GT(green[1], 100);
  EXPECT_LT(green[0], 5);
  EXPECT_LT(green[2], 5);
  EXPECT_EQ(grey[0], grey[1]);
  EXPECT_EQ(grey[1], grey[2]);
  EXPECT_EQ(grey[1], green[1]) << "white times green keeps green's full strength";
}

}  // namespace
}  // namespace sg::test
