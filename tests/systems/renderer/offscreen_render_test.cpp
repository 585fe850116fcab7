// SPDX-License-Identifier: MIT
// Renders an ECS scene through the sandbox's frame graph offscreen and checks floor pixels
// against the lighting formula of docs/ALGORITHMS.md section 2, evaluated here on the CPU from the
// scene's parameters. Validation and synchronization validation are on (GpuTest).
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "ecs/transform_system.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "systems/frame/frame.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"
#include "tests/support/gpu_test.h"
#include "tests/support/shadow_reference.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 160;
constexpr uint32_t height = 120;
// 8-bit quantization (half a step) plus float rounding differences between CPU and shader.
constexpr int tolerance = 3;

float srgb_encode(float linear) {
  linear = glm::clamp(linear, 0.0f, 1.0f);
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// An oriented box: extends half_extent from its center, turned by yaw about +Y.
struct OrientedBox {
  glm::vec3 center;
  glm::vec3 half_extent;
  float yaw = 0.0f;
};

ecs::LocalTransform placement(const OrientedBox& box) {
  return {box.center, glm::angleAxis(box.yaw, glm::vec3(0, 1, 0)), 2.0f * box.half_extent};
}

// A 20 x 20 m floor (top at y = 0), three boxes, and a sun with no shadow: every unoccluded
// floor pixel follows the formula exactly.
struct FloorScene {
  SceneView sandbox;
  std::vector<OrientedBox> boxes;
  scene::Material floor_material;
  scene::DirectionalLight sun;
  glm::vec3 sun_direction;
};

FloorScene make_floor_scene() {
  FloorScene s;
  s.sandbox.scene.name = "floor test";
  const uint32_t box_mesh = scene::add_box_mesh(s.sandbox.scene.meshes);
  s.floor_material.base_color = {0.6f, 0.55f, 0.5f, 1.0f};
  scene::add_instance(s.sandbox.scene, box_mesh, placement({{0, -0.1f, 0}, {10, 0.1f, 10}}),
                      s.floor_material);
  s.boxes = {{{-2, 0.5f, -1}, {0.5f, 0.5f, 0.5f}, 0.3f},
             {{2.5f, 1.0f, 1}, {0.7f, 1.0f, 0.4f}, -0.6f},
             {{0, 0.3f, 3}, {1.0f, 0.3f, 0.6f}, 1.1f}};
  scene::Material box_material;
  box_material.base_color = {0.8f, 0.3f, 0.2f, 1.0f};
  for (const OrientedBox& box : s.boxes)
    scene::add_instance(s.sandbox.scene, box_mesh, placement(box), box_material);

  s.sun.color = {1.0f, 0.95f, 0.9f};
  s.sun.intensity = 0.9f;
  s.sun_direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
  scene::ShadowSettings no_shadow;
  no_shadow.casts_shadow = false;
  // Lights shine down their local -Z, as cameras look: aim it like a camera.
  const glm::quat aim = scene::look_rotation(glm::vec3(0, 10, 0), glm::vec3(0, 10, 0) + s.sun_direction);
  scene::add_light(s.sandbox.scene, s.sun, {glm::vec3(0, 10, 0), aim, glm::vec3(1)}, no_shadow, "sun");
  ecs::update_world_transforms(s.sandbox.scene.world, 0);

  s.sandbox.pose = {{0.0f, 6.0f, 12.0f}, {0.0f, 0.0f, 0.0f}};
  s.sandbox.lens = scene::Camera{};
  s.sandbox.camera_source = "test";
  return s;
}

glm::vec3 expected_floor_color(const FloorScene& s, glm::vec3 point, const glm::vec3& ambient) {
  const scene::Material& m = s.floor_material;
  const glm::vec3 base = glm::vec3(m.base_color);
  const glm::vec3 n(0.0f, 1.0f, 0.0f);
  const glm::vec3 l = -s.sun_direction;
  const glm::vec3 v = glm::normalize(s.sandbox.pose.eye - point);
  const glm::vec3 h = glm::normalize(l + v);
  const glm::vec3 radiance = s.sun.color * s.sun.intensity;
  const float n_dot_l = std::max(glm::dot(n, l), 0.0f);
  const float spec = n_dot_l > 0.0f ? std::pow(std::max(glm::dot(n, h), 0.0f), m.shininess) : 0.0f;
  return ambient * base + base * radiance * n_dot_l + m.specular * radiance * spec;
}

// The scene's picture with `settings`, after three frames (later frames exercise the
// between-frame barriers).
vk::Rgba8Image render(vk::VulkanContext& context, SceneView& scene, const FrameSettings& settings) {
  vk::FrameRing frames(context);
  Frame frame(context, scene, settings, frames.frames_in_flight());
  frame.resize({width, height});
  for (int i = 0; i < 3; ++i) {
    vk::FrameSlot& slot = frames.begin_frame();
    frame.record(slot, 0.0);
    frames.submit();
  }
  frames.wait_idle();
  return vk::read_rgba8(context, frame.image());
}

// Renders the floor scene with `settings` and compares every unoccluded floor pixel with the
// formula.
void expect_floor_matches_formula(vk::VulkanContext& context, const FrameSettings& settings) {
  FloorScene s = make_floor_scene();
  {
    const vk::Rgba8Image image = render(context, s.sandbox, settings);
    ASSERT_EQ(image.width, width);

    const CameraImage camera{s.sandbox.pose, s.sandbox.lens, {width, height}};
    int checked = 0, mismatched = 0;
    for (uint32_t y = 0; y < height; y += 3) {
      for (uint32_t x = 0; x < width; x += 3) {
        const Ray ray = pixel_ray(camera, x, y);
        const std::optional<glm::vec3> hit = hit_floor(ray);
        if (!hit) continue;
        const glm::vec3 point = *hit;
        if (std::abs(point.x) > 9.5f || std::abs(point.z) > 9.5f) continue;
        bool occluded = false;  // by a box, or too close to one's silhouette to be sure
        for (OrientedBox box : s.boxes) {
          box.half_extent += glm::vec3(0.05f);
          occluded = occluded || segment_hits_box(ray.origin, point, {ecs::to_matrix(placement(box))});
        }
        if (occluded) continue;

        const glm::vec3 expected = expected_floor_color(s, point, settings.renderer.ambient);
        const uint8_t* pixel = image.at(x, y);
        ++checked;
        for (int c = 0; c < 3; ++c) {
          const int want = static_cast<int>(std::lround(srgb_encode(expected[c]) * 255.0f));
          if (std::abs(int(pixel[c]) - want) > tolerance) {
            ++mismatched;
            ADD_FAILURE() << "pixel (" << x << ", " << y << ") channel " << c << ": got " << int(pixel[c])
                          << ", formula gives " << want;
            break;
          }
        }
      }
    }
    EXPECT_GT(checked, 300) << "too few unoccluded floor pixels were checked to mean anything";
    EXPECT_EQ(mismatched, 0);
  }
}

using OffscreenRender = GpuTest;

TEST_F(OffscreenRender, FloorMatchesLightingFormula) {
  expect_floor_matches_formula(context, FrameSettings{});
}

// The ambient term per channel (--ambient): fused, and deferred with the lit sum started either way.
TEST_F(OffscreenRender, FloorMatchesLightingFormulaWithAColoredAmbient) {
  FrameSettings settings;
  settings.renderer.ambient = {0.4f, 0.05f, 0.2f};
  settings.renderer.lighting = LightingPath::fused;
  expect_floor_matches_formula(context, settings);
  settings.renderer.lighting = LightingPath::deferred;
  for (const LitSumStart start : {LitSumStart::gbuffer, LitSumStart::pass}) {
    SCOPED_TRACE(std::string(to_string(start)));
    settings.renderer.lit_sum_start = start;
    expect_floor_matches_formula(context, settings);
  }
}

// Deferred lighting reading the light records either way (--light-records): the storage buffer
// GPUs take, and the texel buffer CPU devices take; with ranked filtering, as on GPUs, so that
// the filter floor's pass reads them too.
TEST_F(OffscreenRender, FloorMatchesLightingFormulaWithTheRecordsInEitherBuffer) {
  FrameSettings settings;
  settings.renderer.lighting = LightingPath::deferred;
  settings.renderer.filtered_lights = 1;
  for (const LightRecordsIn records : {LightRecordsIn::storage_buffer, LightRecordsIn::texel_buffer}) {
    SCOPED_TRACE(std::string(to_string(records)));
    settings.renderer.light_records = records;
    expect_floor_matches_formula(context, settings);
  }
}

// The floor scene lit by the sun alone, then with `count` of `light` added, their colors running
// round the hue circle, on a sunflower spiral of radius `spread` `above_floor` over the floor, each
// with `shadow`, by deferred lighting with the light records in each buffer (--light-records):
// how many channels of the texel buffer's picture are brighter than the sun's alone by more than
// 8 levels, and how many differ from the storage buffer's by more than `tolerance` levels.
struct EitherRecordBuffer {
  size_t brighter = 0;
  size_t differing = 0;
};
EitherRecordBuffer light_spiral_from_either_record_buffer(vk::VulkanContext& context, int count, float spread,
                                                          float above_floor, scene::PointLight light,
                                                          const scene::ShadowSettings& shadow,
                                                          int tolerance) {
  FloorScene s = make_floor_scene();
  FrameSettings settings;
  settings.renderer.lighting = LightingPath::deferred;
  const vk::Rgba8Image sun_alone = render(context, s.sandbox, settings);
  for (int i = 0; i < count; ++i) {
    const float radius = spread * std::sqrt(float(i) / float(count));
    const float angle = 2.39996f * float(i);
    light.color = {0.5f + 0.5f * std::sin(angle), 0.6f, 0.5f + 0.5f * std::cos(angle)};
    scene::add_light(s.sandbox.scene, light,
                     {{radius * std::cos(angle), above_floor, radius * std::sin(angle)}}, shadow, "");
  }
  ecs::update_world_transforms(s.sandbox.scene.world, 0);
  std::vector<vk::Rgba8Image> images;
  for (const LightRecordsIn records : {LightRecordsIn::storage_buffer, LightRecordsIn::texel_buffer}) {
    settings.renderer.light_records = records;
    images.push_back(render(context, s.sandbox, settings));
  }
  EitherRecordBuffer counted;
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      for (int c = 0; c < 3; ++c) {
        counted.brighter += images[1].at(x, y)[c] > sun_alone.at(x, y)[c] + 8 ? 1 : 0;
        counted.differing +=
            std::abs(int(images[0].at(x, y)[c]) - int(images[1].at(x, y)[c])) > tolerance ? 1 : 0;
      }
    }
  }
  return counted;
}

// Many unshadowed lights over one spot: on GPUs the lighting pass loads a tile's unshadowed
// lights into shared memory 256 at a time (shaders/light_batch.glsl), which 300 lights overfill;
// the storage-buffer variant that does must light the floor as the texel-buffer one does.
TEST_F(OffscreenRender, ManyUnshadowedLightsLightAlikeFromEitherRecordBuffer) {
  scene::ShadowSettings no_shadow;
  no_shadow.casts_shadow = false;
  const EitherRecordBuffer counted = light_spiral_from_either_record_buffer(
      context, 300, 3.0f, 1.5f, scene::PointLight{glm::vec3(1.0f), 0.005f, 5.0f}, no_shadow, 1);
  EXPECT_GT(counted.brighter, size_t{width} * height / 10) << "the bulbs must light the floor";
  EXPECT_EQ(counted.differing, 0u);
}

// Many shadowed point lights over the floor: where the device's subgroups allow it, a cube
// group's pass reading the records from storage culls the tile's list again for each warp's pixels
// (shaders/tiled_lighting.comp's warp_lists variant, which lavapipe's 8-lane subgroups take too).
// 64 small lights in a 2 m disc, each missing most warps, light the floor as the texel-buffer
// variant, which loops over every listed light, does.
TEST_F(OffscreenRender, ManyShadowedPointLightsLightAlikeFromEitherRecordBuffer) {
  scene::ShadowSettings small_cube;
  small_cube.algorithm = scene::ShadowAlgorithm::pcf;
  small_cube.resolution = 32;
  const EitherRecordBuffer counted = light_spiral_from_either_record_buffer(
      context, 64, 2.0f, 0.4f, scene::PointLight{glm::vec3(1.0f), 0.3f, 0.8f}, small_cube, 0);
  EXPECT_GT(counted.brighter, size_t{width} * height / 50) << "the lights must light the floor";
  EXPECT_EQ(counted.differing, 0u) << "channels that differ at all";
}

}  // namespace
}  // namespace sg::test
