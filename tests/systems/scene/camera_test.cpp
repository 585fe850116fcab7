// SPDX-License-Identifier: MIT
// --camera parsing and framing the scene bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ecs/transform.h"
#include "ecs/transform_system.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene_error.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {
namespace {

TEST(Camera, ParsesSixNumbers) {
  const CameraPose pose = parse_camera("1, 2.5,-3,0,0 ,1e1");
  EXPECT_EQ(pose.eye, glm::vec3(1, 2.5f, -3));
  EXPECT_EQ(pose.target, glm::vec3(0, 0, 10));
}

void expect_camera_error(const std::string& text, const std::string& fragment) {
  try {
    parse_camera(text);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("--camera \"" + text + "\""), std::string::npos) << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

TEST(Camera, RefusesMalformedText) {
  expect_camera_error("1,2,3,4,5", "expected 6 numbers (ex,ey,ez,tx,ty,tz), got 5");
  expect_camera_error("1,2,3,4,5,6,7", "got more");
  expect_camera_error("1,2,x,4,5,6", "value 3: \"x\" is not a finite number");
  expect_camera_error("1,2,3,4,5,", "value 6: \"\" is not a finite number");
  expect_camera_error("1,2,3,4,5,6abc", "value 6");
  expect_camera_error("1,2,3,1,2,3", "eye and target are the same point");
}

TEST(Camera, FramingKeepsTheBoundsInView) {
  Aabb bounds;
  grow(bounds, glm::vec3(-10, 0, -5));
  grow(bounds, glm::vec3(10, 4, 5));
  const float yfov = glm::radians(60.0f);
  const CameraPose pose = frame_bounds(bounds, yfov, 16.0f / 9.0f);
  EXPECT_EQ(pose.target, bounds.center());
  const float radius = glm::length(bounds.extent()) * 0.5f;
  const float distance = glm::length(pose.eye - pose.target);
  // The bounding sphere fits the vertical half angle: sin(half fov) >= radius / distance.
  EXPECT_GE(std::sin(yfov * 0.5f) + 1e-5f, radius / distance);
  EXPECT_GT(pose.eye.y, pose.target.y);  // looking down at the scene
  EXPECT_FALSE(frame_bounds(Aabb{}, yfov, 1.0f).eye == frame_bounds(Aabb{}, yfov, 1.0f).target);
}

TEST(Camera, AddedCameraLooksAtItsTarget) {
  ecs::World world;
  const CameraPose pose{{3, 4, 5}, {0, 1, 0}};
  const ecs::Entity camera = add_camera(world, pose);
  ecs::update_world_transforms(world, 0);
  const ecs::WorldTransform& transform = world.get<ecs::WorldTransform>(camera);
  const glm::vec3 forward = light_direction(transform);  // -Z, as for lights
  const glm::vec3 expected = glm::normalize(pose.target - pose.eye);
  EXPECT_NEAR(glm::dot(forward, expected), 1.0f, 1e-5f);
  EXPECT_EQ(light_position(transform), pose.eye);
  // Straight down works too (up vector fallback).
  EXPECT_NEAR(
      glm::dot(glm::vec3(glm::mat4_cast(look_rotation({0, 5, 0}, {0, 0, 0})) * glm::vec4(0, 0, -1, 0)),
               glm::vec3(0, -1, 0)),
      1.0f, 1e-5f);
}

TEST(ShadowSettingsNames, RoundTripAndRefuseUnknown) {
  for (const ShadowAlgorithm algorithm : all_shadow_algorithms) {
    EXPECT_EQ(parse_enum<ShadowAlgorithm>(to_string(algorithm)), algorithm);
  }
  EXPECT_EQ(to_string(ShadowAlgorithm::pcss_noise), "pcss_noise");
  EXPECT_FALSE(parse_enum<ShadowAlgorithm>("PCF").has_value());
  EXPECT_FALSE(parse_enum<ShadowAlgorithm>("").has_value());
}

}  // namespace
}  // namespace sg::scene
