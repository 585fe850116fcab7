// SPDX-License-Identifier: MIT
// The CPU shadow reference on cases solved by hand.
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "systems/gpu/camera.h"
#include "tests/support/shadow_reference.h"

namespace sg::test {
namespace {

scene::Aabb unit_aabb() { return {glm::vec3(-0.5f), glm::vec3(0.5f)}; }

// A box of `size` centred at `center`, turned by `yaw` radians about +Y.
Box box_at(glm::vec3 center, glm::vec3 size, float yaw = 0.0f) {
  glm::mat4 model = glm::translate(glm::mat4(1.0f), center);
  model = glm::rotate(model, yaw, glm::vec3(0, 1, 0));
  return {glm::scale(model, size)};
}

TEST(SegmentHitsAabb, CrossingTouchingAndMissing) {
  const scene::Aabb box = unit_aabb();
  EXPECT_TRUE(segment_hits_aabb({-2, 0, 0}, {2, 0, 0}, box)) << "through";
  EXPECT_TRUE(segment_hits_aabb({0, 0, 0}, {0, 3, 0}, box)) << "starting inside";
  EXPECT_TRUE(segment_hits_aabb({-2, 0.5f, 0}, {2, 0.5f, 0}, box)) << "along a face";
  EXPECT_TRUE(segment_hits_aabb({-2, 0, 0}, {-0.5f, 0, 0}, box)) << "ending on a face";
  EXPECT_FALSE(segment_hits_aabb({-2, 0, 0}, {-0.6f, 0, 0}, box)) << "stopping short";
  EXPECT_FALSE(segment_hits_aabb({-2, 0.6f, 0}, {2, 0.6f, 0}, box)) << "parallel, above";
  EXPECT_FALSE(segment_hits_aabb({-2, 2, 0}, {2, 1.2f, 0}, box)) << "passing over";
  EXPECT_TRUE(segment_hits_aabb({-1, 1.2f, 0}, {1, -1.2f, 0}, box)) << "diagonal through";
  EXPECT_FALSE(segment_hits_aabb({-2, 0, 0}, {2, 0, 0}, scene::Aabb{})) << "empty box";
}

TEST(SegmentHitsBox, FollowsRotationAndScale) {
  // Turned 45 degrees, the unit box's corner reaches x = 0.707; its axis-aligned twin's face
  // is at 0.5.
  const Box turned = box_at({0, 0, 0}, glm::vec3(1.0f), glm::radians(45.0f));
  EXPECT_TRUE(segment_hits_box({0.65f, 0, -2}, {0.65f, 0, 2}, turned));
  EXPECT_FALSE(segment_hits_box({0.65f, 0, -2}, {0.65f, 0, 2}, box_at({0, 0, 0}, glm::vec3(1.0f))));
  // A corner of the axis-aligned box is outside the turned one.
  EXPECT_FALSE(segment_hits_box({0.45f, 0, 0.45f}, {0.45f, 2, 0.45f}, turned));
  const Box tall = box_at({3, 2, 0}, {0.2f, 4.0f, 0.2f});
  EXPECT_TRUE(segment_hits_box({2, 3.9f, 0}, {4, 3.9f, 0}, tall));
  EXPECT_FALSE(segment_hits_box({2, 4.1f, 0}, {4, 4.1f, 0}, tall));
}

TEST(FloorPointShadowed, ShadowEdgeWhereTheSilhouetteProjects) {
  // Box [-0.5, 0.5] x [1, 2] x [-0.5, 0.5], light above at height 5: the top edge x = 0.5,
  // y = 2 projects from the light onto the floor at x = 0.5 * 5 / 3 = 0.8333.
  const Box box = box_at({0, 1.5f, 0}, glm::vec3(1.0f));
  const glm::vec3 light(0, 5, 0);
  EXPECT_TRUE(floor_point_shadowed({0, 0, 0}, light, box));
  EXPECT_TRUE(floor_point_shadowed({0.82f, 0, 0}, light, box));
  EXPECT_FALSE(floor_point_shadowed({0.85f, 0, 0}, light, box));
  EXPECT_FALSE(floor_point_shadowed({3, 0, 3}, light, box));
  EXPECT_FALSE(floor_point_shadowed({0, 0, 0}, {0, 0.9f, 0}, box)) << "light below the box";
}

CameraImage test_camera(glm::uvec2 size) {
  CameraImage camera;
  camera.pose = {{0.0f, 6.0f, 8.0f}, {0.0f, 0.0f, 0.0f}};
  camera.size = size;
  return camera;
}

TEST(PixelRay, CentrePixelLooksAtTheTargetFromTheNearPlane) {
  const CameraImage camera = test_camera({101, 75});
  const Ray ray = pixel_ray(camera, 50, 37);
  const glm::vec3 forward = glm::normalize(camera.pose.target - camera.pose.eye);
  EXPECT_NEAR(glm::dot(ray.direction, forward), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(ray.origin - camera.pose.eye, forward), camera.lens.znear, 1e-4f);
}

TEST(PixelRay, TopRowLooksHigherAndTheRendererProjectsItBack) {
  const CameraImage camera = test_camera({160, 120});
  EXPECT_GT(pixel_ray(camera, 80, 0).direction.y, pixel_ray(camera, 80, 119).direction.y);
  EXPECT_GT(pixel_ray(camera, 159, 60).direction.x, pixel_ray(camera, 0, 60).direction.x);
  // The floor point of pixel (30, 100) projects back to that pixel's centre.
  const glm::mat4 view_projection =
      projection_matrix(camera.lens, 160.0f / 120.0f) * view_matrix(camera.pose);
  const std::optional<glm::vec3> point = hit_floor(pixel_ray(camera, 30, 100));
  ASSERT_TRUE(point.has_value());
  const glm::vec4 clip = view_projection * glm::vec4(*point, 1.0f);
  const glm::vec2 pixel = (glm::vec2(clip) / clip.w + 1.0f) * 0.5f * glm::vec2(160.0f, 120.0f);
  EXPECT_NEAR(pixel.x, 30.5f, 1e-3f);
  EXPECT_NEAR(pixel.y, 100.5f, 1e-3f);
}

TEST(HitFloor, OnlyAheadOfTheRay) {
  const std::optional<glm::vec3> down = hit_floor({{1, 2, 3}, glm::normalize(glm::vec3(1, -1, 0))});
  ASSERT_TRUE(down.has_value());
  EXPECT_NEAR(down->x, 3.0f, 1e-6f);
  EXPECT_EQ(down->y, 0.0f);
  EXPECT_NEAR(down->z, 3.0f, 1e-6f);
  EXPECT_FALSE(hit_floor({{1, 2, 3}, glm::normalize(glm::vec3(1, 1, 0))}).has_value());
  EXPECT_FALSE(hit_floor({{1, 2, 3}, {1, 0, 0}}).has_value());
}

TEST(ClassifyFloor, BoxHidesFloorFromCameraAndLight) {
  const CameraImage camera = test_camera({64, 48});
  const std::vector<Box> boxes = {box_at({0, 0.5f, 0}, glm::vec3(1.0f))};
  const glm::vec3 light(-3.0f, 4.0f, 0.0f);  // shadow falls towards +x
  const FloorPixels pixels = classify_floor(camera, 5.0f, light, boxes);
  ASSERT_EQ(pixels.pixels.size(), 64u * 48u);

  const auto pixel_of = [&](glm::vec3 world) {
    const glm::mat4 vp = projection_matrix(camera.lens, 64.0f / 48.0f) * view_matrix(camera.pose);
    const glm::vec4 clip = vp * glm::vec4(world, 1.0f);
    const glm::vec2 p = (glm::vec2(clip) / clip.w + 1.0f) * 0.5f * glm::vec2(64.0f, 48.0f);
    return pixels.at(std::uint32_t(p.x), std::uint32_t(p.y));
  };
  EXPECT_EQ(pixel_of({0, 1, 0}), FloorPixel::not_floor) << "the box's top";
  EXPECT_EQ(pixel_of({1.2f, 0, 0}), FloorPixel::shadowed) << "behind the box from the light";
  EXPECT_EQ(pixel_of({-2.0f, 0, 1.5f}), FloorPixel::lit);
  EXPECT_EQ(pixels.at(0, 0), FloorPixel::not_floor) << "beyond the floor's extent";
}

TEST(WithEdgeBand, MarksPixelsNearAChangeOfClass) {
  // 10 x 3: columns 0-4 lit, 5-8 shadowed, column 9 not floor.
  FloorPixels pixels{{10, 3}, {}};
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 10; ++x) {
      pixels.pixels.push_back(x < 5 ? FloorPixel::lit : x < 9 ? FloorPixel::shadowed : FloorPixel::not_floor);
    }
  }
  const FloorPixels banded = with_edge_band(pixels, 2);
  const FloorPixel expected[10] = {FloorPixel::lit,  FloorPixel::lit,      FloorPixel::lit,  FloorPixel::edge,
                                   FloorPixel::edge, FloorPixel::edge,     FloorPixel::edge, FloorPixel::edge,
                                   FloorPixel::edge, FloorPixel::not_floor};
  for (std::uint32_t y = 0; y < 3; ++y) {
    for (std::uint32_t x = 0; x < 10; ++x) {
      EXPECT_EQ(banded.at(x, y), expected[x]) << "pixel " << x << ", " << y;
    }
  }
  EXPECT_EQ(with_edge_band(pixels, 0).pixels, pixels.pixels) << "no band";
}

}  // namespace
}  // namespace sg::test
