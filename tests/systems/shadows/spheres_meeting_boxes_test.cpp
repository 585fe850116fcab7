// SPDX-License-Identifier: MIT
// Which spheres meet any of a set of boxes: the grid must find exactly what testing every pair
// finds.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "systems/shadows/spheres_meeting_boxes.h"

namespace sg::shadows {
namespace {

std::vector<uint8_t> every_pair(std::span<const glm::vec4> spheres, std::span<const scene::Aabb> boxes) {
  std::vector<uint8_t> met(spheres.size(), 0);
  for (size_t i = 0; i < spheres.size(); ++i) {
    for (const scene::Aabb& box : boxes) met[i] = met[i] != 0 || sphere_meets_box(spheres[i], box);
  }
  return met;
}

std::vector<uint8_t> with_grid(std::span<const glm::vec4> spheres, std::span<const scene::Aabb> boxes) {
  SpheresMeetingBoxes finder;
  std::vector<uint8_t> met(spheres.size(), 0);
  finder.find(spheres, boxes, met);
  return met;
}

TEST(SpheresMeetingBoxes, SphereMeetsBoxWhenTheyIntersectOrTouch) {
  const scene::Aabb box{glm::vec3(0.0f), glm::vec3(1.0f)};
  EXPECT_TRUE(sphere_meets_box({0.5f, 0.5f, 0.5f, 0.1f}, box));  // inside
  EXPECT_TRUE(sphere_meets_box({2.0f, 0.5f, 0.5f, 1.0f}, box));  // touching a face
  EXPECT_FALSE(sphere_meets_box({2.0f, 0.5f, 0.5f, 0.9f}, box));
  // Near a corner: within the radius along each axis but not in distance.
  EXPECT_FALSE(sphere_meets_box({1.6f, 1.6f, 1.6f, 1.0f}, box));
  EXPECT_TRUE(sphere_meets_box({1.5f, 1.5f, 1.5f, 0.9f}, box));
  // The box inside the sphere.
  EXPECT_TRUE(sphere_meets_box({0.5f, 0.5f, 0.5f, 10.0f}, box));
  // Above the box in y, which the grid ignores.
  EXPECT_FALSE(sphere_meets_box({0.5f, 5.0f, 0.5f, 1.0f}, box));
}

TEST(SpheresMeetingBoxes, LeavesElementsAlreadySetAlone) {
  SpheresMeetingBoxes finder;
  const std::vector<glm::vec4> spheres{{0.0f, 0.0f, 0.0f, 1.0f}, {100.0f, 0.0f, 0.0f, 1.0f}};
  const std::vector<scene::Aabb> boxes{{glm::vec3(-0.5f), glm::vec3(0.5f)}};
  std::vector<uint8_t> met{0, 1};
  finder.find(spheres, boxes, met);
  EXPECT_EQ(met, (std::vector<uint8_t>{1, 1}));
}

// Random scenes with the cases that trip grids: a few huge spheres (they stretch no grid but
// cover every cell), radius 0, boxes far outside the spheres' area, boxes covering everything.
TEST(SpheresMeetingBoxes, FindsExactlyWhatTestingEveryPairFinds) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-100.0f, 100.0f);
  std::uniform_real_distribution<float> radius(0.0f, 6.0f);
  std::uniform_real_distribution<float> size(0.0f, 8.0f);
  SpheresMeetingBoxes finder;  // reused, as a frame reuses it
  for (int scene = 0; scene < 20; ++scene) {
    std::vector<glm::vec4> spheres;
    for (int i = 0; i < 2'000; ++i) {
      // Braces: their elements are drawn left to right under every compiler.
      spheres.push_back(
          glm::vec4{coordinate(random), coordinate(random) * 0.1f, coordinate(random), radius(random)});
    }
    spheres[0].w = 500.0f;
    spheres[1].w = 0.0f;
    spheres[2] = {1'000.0f, 0.0f, -1'000.0f, 50.0f};
    std::vector<scene::Aabb> boxes;
    for (int b = 0; b < 100; ++b) {
      const glm::vec3 min{coordinate(random), coordinate(random) * 0.1f, coordinate(random)};
      boxes.push_back({min, min + glm::vec3{size(random), size(random), size(random)}});
    }
    boxes.push_back({glm::vec3(990.0f, -1.0f, -1'010.0f), glm::vec3(995.0f, 1.0f, -1'005.0f)});
    boxes.push_back({glm::vec3(-400.0f, -1.0f, 300.0f), glm::vec3(-399.0f, 1.0f, 301.0f)});
    if (scene % 5 == 0) boxes.push_back({glm::vec3(-200.0f), glm::vec3(200.0f)});

    std::vector<uint8_t> met(spheres.size(), 0);
    finder.find(spheres, boxes, met);
    ASSERT_EQ(met, every_pair(spheres, boxes)) << "scene " << scene;
  }
}

TEST(SpheresMeetingBoxes, SpheresAllAtOnePointOrOnALine) {
  const std::vector<glm::vec4> one_point(50, glm::vec4(3.0f, 0.0f, 3.0f, 0.0f));
  const std::vector<scene::Aabb> at_the_point{{glm::vec3(3.0f), glm::vec3(4.0f)}};
  EXPECT_EQ(with_grid(one_point, at_the_point), every_pair(one_point, at_the_point));

  std::vector<glm::vec4> on_a_line;
  for (int i = 0; i < 1'000; ++i) on_a_line.emplace_back(float(i) * 1'000.0f, 0.0f, 5.0f, 0.5f);
  const std::vector<scene::Aabb> boxes{{glm::vec3(4'999.0f, -1.0f, 4.0f), glm::vec3(5'000.0f, 1.0f, 5.0f)},
                                       {glm::vec3(-10.0f), glm::vec3(-9.0f)}};
  const std::vector<uint8_t> met = with_grid(on_a_line, boxes);
  EXPECT_EQ(met, every_pair(on_a_line, boxes));
  EXPECT_EQ(met[5], 1);
}

}  // namespace
}  // namespace sg::shadows
