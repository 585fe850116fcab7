// SPDX-License-Identifier: MIT
#include "sandbox/fly_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace sg::sandbox {

void fly(FlyCamera& camera, scene::CameraPose& pose, const FlyInput& input, float seconds,
         const scene::Aabb& scene, float yfov) {
  const glm::vec3 world_up(0.0f, 1.0f, 0.0f);
  glm::vec3 forward = glm::normalize(pose.target - pose.eye);
  camera.speed = std::clamp(camera.speed * std::pow(camera.speed_step, input.scroll), 0.01f, 10'000.0f);
  if (input.look && input.mouse_delta != glm::vec2(0.0f)) {
    const float limit = glm::radians(89.0f);
    const float yaw = std::atan2(forward.x, -forward.z) + input.mouse_delta.x * camera.radians_per_pixel;
    const float pitch = std::clamp(
        std::asin(std::clamp(forward.y, -1.0f, 1.0f)) - input.mouse_delta.y * camera.radians_per_pixel,
        -limit, limit);
    forward = {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
    pose.up = world_up;
  }
  const glm::vec3 right = glm::normalize(glm::cross(forward, scene::camera_up(forward, world_up)));
  pose.eye +=
      (right * input.move.x + world_up * input.move.y + forward * input.move.z) * camera.speed * seconds;
  if (input.frame_scene && !scene.empty()) {
    const float radius = std::max(0.5f * glm::length(scene.extent()), 0.01f);
    pose.eye = scene.center() - forward * (radius / std::sin(0.5f * yfov));
  }
  pose.target = pose.eye + forward;
}

}  // namespace sg::sandbox
