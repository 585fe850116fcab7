// SPDX-License-Identifier: MIT
// shadowgraph-reference --whole-frame on lavapipe: with one light on it measures what the
// per-light mode measures, a starved shadow budget comes out worse than the default, and a frame
// with more pairs than the probe holds is measured on a sample that says so, and the light lists'
// pairs are counted as the frame holds them, with those that light a pixel.
#include <gtest/gtest.h>

#include <cmath>

#include "rendergraph/device/frame_ring.h"
#include "systems/frame/frame.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/headless_frames.h"
#include "systems/frame/scene_view.h"
#include "tests/support/gpu_test.h"
#include "tools/reference/run_reference.h"
#include "tools/reference/whole_frame.h"

namespace sg::test {
namespace {

class WholeFrame : public GpuTest {
 protected:
  // A small hall from afar, every light hard, standing still.
  static FrameSettings small_hall() {
    FrameSettings options;
    options.width = 320;
    options.height = 180;
    options.scene = "stress";
    options.scene_params.triangles = 20000;
    options.scene_params.point_lights = 8;
    options.scene_params.spot_lights = 8;
    options.animate = false;
    options.algorithm = scene::ShadowAlgorithm::hard;
    return options;
  }
};

TEST_F(WholeFrame, AgreesWithThePerLightModeWhenOneLightIsOn) {
  reference::ReferenceSettings per_light;
  per_light.algorithms = {scene::ShadowAlgorithm::hard};
  per_light.light_filter = "sun";
  per_light.soft_samples = 4;
  const reference::ReferenceReport alone = reference::run_reference(context, small_hall(), per_light);
  ASSERT_EQ(alone.lights.size(), 1u);
  const reference::ShadowMetrics& expected = alone.lights[0].runs.at(0).metrics;

  reference::WholeFrameSettings frame_mode;
  frame_mode.light_filter = "sun";
  frame_mode.soft_samples = 4;
  const reference::WholeFrameReport frame = reference::run_whole_frame(context, small_hall(), frame_mode);
  ASSERT_EQ(frame.worst.size(), 1u) << "only the sun's pairs are measured";
  EXPECT_EQ(frame.worst[0].name, "sun");
  EXPECT_EQ(frame.sampled_fraction, 1.0);
  ASSERT_GT(frame.error.lit_pixels, 1000u);
  // The sun's map (1,024 texels over the whole hall) misclassifies a few of its pixels.
  ASSERT_GT(expected.misclassified, 0.001);
  EXPECT_NEAR(frame.error.misclassified, expected.misclassified, 0.25 * expected.misclassified);
}

TEST_F(WholeFrame, AStarvedShadowBudgetIsReportedWorse) {
  FrameSettings options = small_hall();
  options.scene_params.point_lights = 500;
  options.scene_params.spot_lights = 500;
  options.camera_name = "street";
  options.algorithm.reset();  // each light's own
  reference::WholeFrameSettings frame_mode;
  frame_mode.soft_samples = 4;
  const reference::WholeFrameReport full = reference::run_whole_frame(context, options, frame_mode);
  options.renderer.shadow_memory_mib = 16;
  const reference::WholeFrameReport starved = reference::run_whole_frame(context, options, frame_mode);

  ASSERT_GT(full.shadowed_lights, 1000u);
  ASSERT_GT(full.error.lit_pixels, 20000u);
  EXPECT_EQ(starved.error.lit_pixels, full.error.lit_pixels) << "the same frame, only the shadows differ";
  EXPECT_GT(starved.error.misclassified, 2.0 * full.error.misclassified);
  EXPECT_GT(starved.error.mae, full.error.mae);
}

TEST_F(WholeFrame, AFrameWithMorePairsThanRoomIsMeasuredOnASample) {
  FrameSettings options;
  options.width = 160;
  options.height = 90;
  reference::WholeFrameSettings frame_mode;
  frame_mode.soft_samples = 4;
  const reference::WholeFrameReport all = reference::run_whole_frame(context, options, frame_mode);
  frame_mode.pairs_per_pixel = 1;
  const reference::WholeFrameReport sampled = reference::run_whole_frame(context, options, frame_mode);

  EXPECT_EQ(all.sampled_fraction, 1.0);
  EXPECT_GT(all.frame_pairs, 3u * 160 * 90 / 2) << "the default scene's lights overlap";
  EXPECT_LT(sampled.sampled_fraction, 0.5);
  EXPECT_LE(sampled.traced_pairs, 160u * 90);
  EXPECT_EQ(sampled.frame_pairs, all.frame_pairs);
  EXPECT_NEAR(sampled.error.mae, all.error.mae, 0.5 * all.error.mae + 0.002);
  EXPECT_FALSE(sampled.lighting_list_pairs) << "a sample cannot tell which pairs light nothing";
  EXPECT_EQ(sampled.list_pairs, all.list_pairs);
}

TEST_F(WholeFrame, CountsTheListPairsAndThoseThatLightAPixel) {
  FrameSettings options = small_hall();  // standing still: every frame has the same lists
  options.renderer.lighting = LightingPath::deferred;
  const reference::WholeFrameReport report = reference::run_whole_frame(context, options, {});

  // The lists as the renderer counts them, in frames of their own.
  SceneView view = load_scene_view(options, float(options.width) / float(options.height));
  vk::FrameRing ring(context);
  Frame frame(context, view, options, ring.frames_in_flight());
  frame.resize({options.width, options.height});
  GpuTimeLog times;
  render_headless_frames(frame, ring, 4, times);
  ASSERT_FALSE(frame.light_list_pairs().empty());
  EXPECT_EQ(report.list_pairs, uint64_t(frame.light_list_pairs().back()));
  ASSERT_TRUE(report.lighting_list_pairs);
  EXPECT_GE(*report.lighting_list_pairs, uint64_t(frame.light_list_pairs().back()) / 4);
  // From afar the spots, pointing down, light a few tiles of those the culling lists them in.
  EXPECT_LT(*report.lighting_list_pairs, report.list_pairs);
}

}  // namespace
}  // namespace sg::test
