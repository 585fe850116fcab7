// SPDX-License-Identifier: MIT
// The Embree reference against the analytic one (tests/support/shadow_reference.h) on the
// floor-and-box scene: surface points taken back from the engine's depth buffer must lie on the
// floor, and the hard visibility traced from them must say lit and shadowed where exact ray
// casting against the box does, outside a one-pixel band around the edge.
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "ecs/jobs/thread_pool.h"
#include "tests/support/floor_box_scene.h"
#include "tests/support/gpu_test.h"
#include "tools/reference/engine_shade.h"
#include "tools/reference/ray_scene.h"
#include "tools/reference/reference_lights.h"
#include "tools/reference/scene_triangles.h"
#include "tools/reference/surface_points.h"
#include "tools/reference/visibility.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 160;
constexpr uint32_t height = 120;

class EmbreeReference : public GpuTest {
 protected:
  struct Agreement {
    int compared = 0;
    int shadowed = 0;
    int disagree = 0;
    int off_the_floor = 0;  // floor pixels whose surface point is not on y = 0
  };

  Agreement compare(const ShadowScene& s) {
    const CameraImage view = floor_camera({width, height});
    SceneView scene{build_shadow_scene(s, s.intensity), view.pose, view.lens, "test"};
    FrameSettings options;
    options.width = width;
    options.height = height;
    jobs::ThreadPool pool;
    const reference::SceneTriangles triangles = reference::scene_triangles(scene.scene);
    const reference::RayScene casters(triangles.casters);
    const reference::RayScene surfaces(triangles.surfaces);
    reference::EngineShade engine(context, scene, options);
    const reference::SurfacePoints points =
        reference::surface_points(engine.depth(), view.pose, view.lens, surfaces, pool);
    const std::vector<reference::ReferenceLight> lights = reference::shadowed_lights(scene.scene);
    EXPECT_EQ(lights.size(), 1u);
    const std::vector<float> traced = reference::hard_visibility(casters, points, lights.at(0), pool);

    const FloorPixels exact = floor_reference(s, {width, height}, 1);
    Agreement a;
    for (size_t i = 0; i < traced.size(); ++i) {
      const FloorPixel expected = exact.pixels[i];
      if (expected != FloorPixel::lit && expected != FloorPixel::shadowed) continue;
      if (!points.points[i].valid) continue;
      ++a.compared;
      a.off_the_floor += std::abs(points.points[i].position.y) > 1e-3f;
      a.shadowed += expected == FloorPixel::shadowed;
      a.disagree += (traced[i] < 0.5f) != (expected == FloorPixel::shadowed);
    }
    return a;
  }
};

TEST_F(EmbreeReference, HardSpotVisibilityAgreesWithTheAnalyticReference) {
  const Agreement a = compare(ShadowScene{});
  ASSERT_GT(a.compared, 5000);
  ASSERT_GT(a.shadowed, 100) << "the box must cast a visible shadow";
  EXPECT_EQ(a.off_the_floor, 0) << "depth-buffer points must lie on the floor";
  EXPECT_LE(a.disagree, a.compared / 1000) << a.disagree << " of " << a.compared;
}

TEST_F(EmbreeReference, HardPointVisibilityAgreesWithTheAnalyticReference) {
  ShadowScene s;
  s.kind = LightKind::point;
  s.light_position = {-2.5f, 4.0f, -1.5f};
  const Agreement a = compare(s);
  ASSERT_GT(a.compared, 5000);
  ASSERT_GT(a.shadowed, 100);
  EXPECT_EQ(a.off_the_floor, 0);
  EXPECT_LE(a.disagree, a.compared / 1000) << a.disagree << " of " << a.compared;
}

// A light's reference is traced against the casters its caster mask names, as its maps draw them.
TEST(CasterScenes, ALightsRaysMeetOnlyTheCastersOnItsMasksLayers) {
  reference::SceneTriangles triangles;
  const auto add_roof = [&](float height, scene::LayerMask layers) {
    for (const glm::vec3 corner :
         {glm::vec3(-5, height, -5), glm::vec3(5, height, -5), glm::vec3(0, height, 5)}) {
      triangles.casters.push_back(corner);
    }
    triangles.caster_layers.push_back(layers);
  };
  add_roof(1.0f, 0x01);
  add_roof(2.0f, 0x06);
  const std::array<scene::LayerMask, 4> masks{0x01, 0x02, 0x08, 0x01};
  const reference::CasterScenes casters(triangles, masks);
  const auto first_hit = [&](scene::LayerMask mask) {
    const auto hit = casters.of(mask).intersect({0, 0, 0}, {0, 1, 0});
    return hit ? hit->distance : 0.0f;
  };
  EXPECT_FLOAT_EQ(first_hit(0x01), 1.0f);
  EXPECT_FLOAT_EQ(first_hit(0x02), 2.0f) << "the lower roof is on layer 0 alone";
  EXPECT_FLOAT_EQ(first_hit(0x08), 0.0f) << "no roof on layer 3";
  EXPECT_THROW(casters.of(0x10), std::logic_error);
}

}  // namespace
}  // namespace sg::test
