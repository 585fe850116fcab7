// SPDX-License-Identifier: MIT
// The window's fly camera, without a window: what each input does to the pose.
#include <cmath>

#include <gtest/gtest.h>

#include "sandbox/fly_camera.h"

namespace sg::sandbox {
namespace {

void expect_near(const glm::vec3& actual, const glm::vec3& expected) {
  EXPECT_LT(glm::length(actual - expected), 1e-4f)
      << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", "
      << expected.y << ", " << expected.z << ")";
}

const scene::CameraPose looking_down_minus_z{{0, 1, 0}, {0, 1, -1}};
constexpr float fov = 1.0f;

TEST(FlyCamera, MovesAlongTheViewAndWorldUp) {
  FlyCamera camera;  // 5 m/s
  scene::CameraPose pose = looking_down_minus_z;
  FlyInput input;
  input.move = {0, 0, 1};  // W
  fly(camera, pose, input, 2.0f, {}, fov);
  expect_near(pose.eye, {0, 1, -10});
  input.move = {1, 1, 0};  // D and E
  fly(camera, pose, input, 1.0f, {}, fov);
  expect_near(pose.eye, {5, 6, -10});
  expect_near(pose.target - pose.eye, {0, 0, -1});  // moving does not turn
}

TEST(FlyCamera, LookingTurnsOnlyWhileTheButtonIsHeldAndStopsShortOfVertical) {
  FlyCamera camera;
  scene::CameraPose pose = looking_down_minus_z;
  FlyInput input;
  input.mouse_delta = {100, 0};
  fly(camera, pose, input, 0.1f, {}, fov);
  expect_near(pose.target - pose.eye, {0, 0, -1});  // not held: nothing
  input.look = true;
  input.mouse_delta = {glm::radians(90.0f) / camera.radians_per_pixel, 0};  // a quarter turn right
  fly(camera, pose, input, 0.1f, {}, fov);
  expect_near(pose.target - pose.eye, {1, 0, 0});
  input.mouse_delta = {0, -100000};  // far up: held at 89 degrees
  fly(camera, pose, input, 0.1f, {}, fov);
  EXPECT_NEAR(std::asin(glm::normalize(pose.target - pose.eye).y), glm::radians(89.0f), 1e-4f);
}

TEST(FlyCamera, TheWheelScalesTheSpeed) {
  FlyCamera camera;
  scene::CameraPose pose = looking_down_minus_z;
  FlyInput input;
  input.scroll = 2;
  fly(camera, pose, input, 0.0f, {}, fov);
  EXPECT_FLOAT_EQ(camera.speed, 5.0f * 1.25f * 1.25f);
  input.scroll = -100;
  fly(camera, pose, input, 0.0f, {}, fov);
  EXPECT_FLOAT_EQ(camera.speed, 0.01f);  // never stops altogether
}

TEST(FlyCamera, FramingKeepsTheDirectionAndFitsTheScene) {
  FlyCamera camera;
  scene::CameraPose pose{{40, 3, 7}, {41, 3, 7}};  // looking down +X, far away
  FlyInput input;
  input.frame_scene = true;
  const scene::Aabb room{glm::vec3(-2.0f), glm::vec3(2.0f)};
  fly(camera, pose, input, 0.0f, room, fov);
  expect_near(pose.target - pose.eye, {1, 0, 0});
  const float radius = 0.5f * glm::length(room.extent());
  // The bounding sphere fits: seen from the eye, it spans at most the field of view.
  EXPECT_NEAR(std::asin(radius / glm::length(pose.eye - room.center())), 0.5f * fov, 1e-4f);
  expect_near(glm::normalize(room.center() - pose.eye), {1, 0, 0});
}

}  // namespace
}  // namespace sg::sandbox
