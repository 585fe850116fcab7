// SPDX-License-Identifier: MIT
// The batched shadow views' two rasterizers, the raster hardware (shadow_batch.vert) and compute
// (shadow_raster.comp), write the same depths into the same tiles, on lavapipe with validation.
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "ecs/transform_system.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "systems/frame/frame.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

// A floor larger than every map, a crate and a pillar; a beam (orthographic), a spot and a point
// light whose views clip the floor on every side and the pillar at their near planes. `crate`,
// `point_light`: where to say which entities the crate and the point light are.
SceneView clipped_scene(ecs::Entity* crate = nullptr, uint32_t resolution = 256,
                        ecs::Entity* point_light = nullptr) {
  SceneView scene;
  scene.scene.name = "clipped";
  const uint32_t box = scene::add_box_mesh(scene.scene.meshes);
  const uint32_t column = scene::add_cylinder_mesh(scene.scene.meshes, 16);
  const scene::Material grey;
  scene::add_instance(scene.scene, box, {{0.0f, -0.5f, 0.0f}, glm::quat(1, 0, 0, 0), {40.0f, 1.0f, 40.0f}},
                      grey);
  const ecs::Entity crate_entity = scene::add_instance(
      scene.scene, box, {{1.0f, 0.5f, 0.5f}, glm::quat(1, 0, 0, 0), {1.0f, 1.0f, 1.0f}}, grey);
  if (crate) *crate = crate_entity;
  scene::add_instance(scene.scene, column, {{-1.0f, 2.0f, 0.0f}, glm::quat(1, 0, 0, 0), {0.6f, 4.0f, 0.6f}},
                      grey);
  scene::ShadowSettings shadow;
  // 256: llvmpipe caps an invocation's loop iterations (shadow_raster.comp), so larger tiles are
  // left to GPUs.
  shadow.resolution = resolution;
  scene::add_light(
      scene.scene, scene::CylinderLight{glm::vec3(1.0f), 1.0f, 1.0f, 2.0f},
      {glm::vec3(0.0f, 4.0f, 0.0f), scene::look_rotation({0, 4, 0}, {0.01f, 0, 0}), glm::vec3(1.0f)}, shadow,
      "beam");
  scene::SpotLight spot;
  spot.range = 12.0f;
  spot.outer_cone = 0.7f;
  scene::add_light(
      scene.scene, spot,
      {glm::vec3(-2.2f, 2.0f, 0.3f), scene::look_rotation({-2.2f, 2, 0.3f}, {3, 0, 0}), glm::vec3(1.0f)},
      shadow, "spot");
  scene::PointLight point;
  point.range = 8.0f;
  const ecs::Entity point_entity =
      scene::add_light(scene.scene, point, {glm::vec3(-0.2f, 1.5f, 0.9f)}, shadow, "point");
  if (point_light) *point_light = point_entity;
  ecs::update_world_transforms(scene.scene.world, 0);
  scene.pose = {{0.0f, 6.0f, 6.0f}, {0.0f, 0.0f, 0.0f}};
  return scene;
}

// Every texel of every shadow view of `frame`'s lights, in view order (maps, then cube faces).
std::vector<float> view_depths(vk::VulkanContext& context, const Frame& frame) {
  const shadows::FrameLights& lights = frame.renderer().lights();
  std::vector<float> out;
  const auto read = [&](const shadows::AtlasTile& tile) {
    const vk::DepthImage page = vk::read_depth_layer(context, frame.renderer().shadow_atlas().image(),
                                                     tile.page, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
    for (uint32_t y = 0; y < tile.size; ++y) {
      for (uint32_t x = 0; x < tile.size; ++x) out.push_back(page.at(tile.x + x, tile.y + y));
    }
  };
  for (const shadows::ShadowMapView& map : lights.maps) read(map.tile);
  for (const shadows::ShadowCubeView& cube : lights.cubes) {
    for (const shadows::AtlasTile& tile : cube.tiles) read(tile);
  }
  return out;
}

// Texels whose depths differ by more than `tolerance`.
size_t differing(const std::vector<float>& a, const std::vector<float>& b, float tolerance = 1e-6f) {
  size_t count = 0;
  for (size_t i = 0; i < a.size(); ++i) count += std::abs(a[i] - b[i]) > tolerance;
  return count;
}

class ShadowRasterTest : public GpuTest {
 protected:
  // A 64x48 frame of `scene`, still, whose shadows `raster` draws (set_shadow_raster may change
  // it between frames when `raster` is compute).
  std::unique_ptr<Frame> frame_of(SceneView& scene, shadows::ShadowRaster raster) {
    FrameSettings options;
    options.renderer.shadow_raster = raster;
    options.animate = false;
    auto frame = std::make_unique<Frame>(context, scene, options, frames.frames_in_flight());
    frame->resize({64, 48});
    return frame;
  }
  // Records one frame of `frame` and waits for it; the frame's shadow counts.
  const shadows::ShadowScheduleStats& draw(Frame& frame) {
    frame.record(frames.begin_frame(), 0.0);
    frames.submit();
    frames.wait_idle();
    return frame.renderer().shadow_stats();
  }

  // Every texel of every shadow view of `resolution` texels, in view order, rendered with `raster`.
  std::vector<float> depths(shadows::ShadowRaster raster, uint32_t resolution) {
    SceneView scene = clipped_scene(nullptr, resolution);
    const std::unique_ptr<Frame> frame = frame_of(scene, raster);
    draw(*frame);
    EXPECT_EQ(frame->renderer().lights().maps.size(), 2u);
    EXPECT_EQ(frame->renderer().lights().cubes.size(), 1u);
    return view_depths(context, *frame);
  }

  // The compute raster's views of `resolution` texels hold what the hardware raster's hold.
  void expect_rasters_alike(uint32_t resolution) {
    const std::vector<float> hardware = depths(shadows::ShadowRaster::hardware, resolution);
    const std::vector<float> compute = depths(shadows::ShadowRaster::compute, resolution);
    ASSERT_EQ(hardware.size(), compute.size());
    ASSERT_EQ(hardware.size(), 8u * resolution * resolution);
    // Texel centres on a triangle's edge may go either way, and depths differ by rounding.
    const auto covered =
        std::count_if(hardware.begin(), hardware.end(), [](float depth) { return depth < 1.0f; });
    EXPECT_GT(size_t(covered), hardware.size() / 2) << "the floor fills most views";
    const size_t different = differing(hardware, compute, 1e-4f);
    EXPECT_LT(different, hardware.size() / 200) << different << " of " << hardware.size() << " texels differ";
  }

  vk::FrameRing frames{context};
};

// Tiles of 256 texels: the compute raster's depths reach the atlas by a copy.
TEST_F(ShadowRasterTest, ComputeRasterWritesWhatTheHardwareWrites) { expect_rasters_alike(256); }

// Tiles of 32 texels, all eight views' 8,192 texels fewer than a copied rectangle: their depths
// reach the atlas by a draw.
TEST_F(ShadowRasterTest, ComputeRasterWritesWhatTheHardwareWritesInSmallTiles) { expect_rasters_alike(32); }

// The compute raster keeps a static layer per map: once the crate has started moving, the maps it
// crosses redraw from their layers with the crate alone, and must hold what drawing every caster
// into them holds.
TEST_F(ShadowRasterTest, MovingCastersOverStaticLayersMatchDrawingEveryCaster) {
  ecs::Entity crate;
  // 512 texels: the layers' passes share a tile among workgroups past 256 (65,536 texels).
  SceneView scene = clipped_scene(&crate, 512);
  const std::unique_ptr<Frame> layered = frame_of(scene, shadows::ShadowRaster::compute);
  draw(*layered);
  const std::vector<float> still = view_depths(context, *layered);
  ASSERT_EQ(still.size(), 8u * 512 * 512);
  for (const float x : {1.3f, 1.6f, 1.9f}) {
    scene.scene.world.get_mut<ecs::LocalTransform>(crate).translation.x = x;
    draw(*layered);
  }
  // The first move left the layers where the crate stood: drawn with every caster; the next two
  // drew the crate alone over them.
  EXPECT_EQ(layered->renderer().shadow_stats().views_moving_only, 2u + 6u) << "both maps and the cube";
  const std::vector<float> moved = view_depths(context, *layered);

  const std::unique_ptr<Frame> fresh = frame_of(scene, shadows::ShadowRaster::compute);
  EXPECT_EQ(draw(*fresh).views_moving_only, 0u);
  const std::vector<float> everything = view_depths(context, *fresh);
  ASSERT_EQ(moved.size(), everything.size());
  EXPECT_EQ(differing(moved, everything), 0u);
  EXPECT_GT(differing(moved, still), 100u) << "the crate's shadow moved";
}

// A frame drawn by the raster hardware keeps no static layers: a map it drew with every caster
// (the point light moved) must draw every caster again when the crate next moves, not restore
// the layer it had before the light moved.
TEST_F(ShadowRasterTest, AHardwareFrameKeepsNoStaticLayers) {
  ecs::Entity crate;
  ecs::Entity point;
  SceneView scene = clipped_scene(&crate, 256, &point);
  const std::unique_ptr<Frame> layered = frame_of(scene, shadows::ShadowRaster::compute);
  draw(*layered);
  scene.scene.world.get_mut<ecs::LocalTransform>(crate).translation.x = 1.3f;  // out of the layers
  draw(*layered);
  scene.scene.world.get_mut<ecs::LocalTransform>(point).translation.x = 0.1f;
  layered->renderer().set_shadow_raster(shadows::ShadowRaster::hardware);
  EXPECT_EQ(draw(*layered).views_rendered, 6u) << "the point light's cube";
  scene.scene.world.get_mut<ecs::LocalTransform>(crate).translation.x = 1.6f;
  layered->renderer().set_shadow_raster(shadows::ShadowRaster::compute);
  EXPECT_EQ(draw(*layered).views_moving_only, 2u) << "the maps alone";
  const std::vector<float> moved = view_depths(context, *layered);

  const std::unique_ptr<Frame> fresh = frame_of(scene, shadows::ShadowRaster::compute);
  draw(*fresh);
  const std::vector<float> everything = view_depths(context, *fresh);
  ASSERT_EQ(moved.size(), everything.size());
  EXPECT_EQ(differing(moved, everything), 0u);
}

}  // namespace
}  // namespace sg::test
