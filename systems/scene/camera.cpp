// SPDX-License-Identifier: MIT
#include "systems/scene/camera.h"

#include <charconv>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "ecs/transform.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {
namespace {

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

}  // namespace

CameraPose parse_camera(std::string_view text) {
  const std::string where = "--camera \"" + std::string(text) + "\"";
  float values[6];
  std::size_t count = 0;
  std::string_view rest = text;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view field = trim(rest.substr(0, comma));
    if (count == 6) throw SceneError(where, "value list", "expected 6 numbers, got more");
    float value = 0.0f;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || error != std::errc{} || end != field.data() + field.size() ||
        !std::isfinite(value)) {
      throw SceneError(where, "value " + std::to_string(count + 1),
                       "\"" + std::string(field) +
                           "\" is not a finite number "
                           "(expected ex,ey,ez,tx,ty,tz)");
    }
    values[count++] = value;
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  if (count != 6) {
    throw SceneError(where, "value list",
                     "expected 6 numbers (ex,ey,ez,tx,ty,tz), got " + std::to_string(count));
  }
  const CameraPose pose{{values[0], values[1], values[2]}, {values[3], values[4], values[5]}};
  if (pose.eye == pose.target) throw SceneError(where, "eye", "eye and target are the same point");
  return pose;
}

CameraPose frame_bounds(const Aabb& bounds, float yfov, float aspect) {
  if (bounds.empty()) return {{0.0f, 2.0f, 5.0f}, {0.0f, 0.0f, 0.0f}};
  const glm::vec3 center = bounds.center();
  const float radius = std::max(glm::length(bounds.extent()) * 0.5f, 1e-3f);
  const float half_y = yfov * 0.5f;
  const float half_x = std::atan(std::tan(half_y) * (aspect > 0.0f ? aspect : 1.0f));
  const float distance = radius / std::sin(std::min(half_x, half_y));
  const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, 0.5f, 1.0f));
  return {center + direction * distance, center};
}

glm::vec3 camera_up(const glm::vec3& forward, const glm::vec3& up) {
  const float length = glm::length(up);
  if (length > 0.0f && std::abs(glm::dot(forward, up / length)) < 0.999f) return up / length;
  // Any axis perpendicular to forward will do; take the world axis least along it.
  const glm::vec3 a = glm::abs(forward);
  const glm::vec3 axis = a.x <= a.y && a.x <= a.z ? glm::vec3(1, 0, 0)
                         : a.y <= a.z             ? glm::vec3(0, 1, 0)
                                                  : glm::vec3(0, 0, 1);
  return glm::normalize(axis - forward * glm::dot(axis, forward));
}

CameraPose camera_pose(const ecs::WorldTransform& world) {
  const glm::vec3 eye(world.matrix[3]);
  const glm::vec3 forward = glm::normalize(-glm::vec3(world.matrix[2]));
  return {eye, eye + forward, glm::normalize(glm::vec3(world.matrix[1]))};
}

glm::quat look_rotation(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
  const glm::vec3 forward = glm::normalize(target - eye);
  // lookAt builds the view matrix (world to camera); the entity's rotation is its inverse.
  return glm::quat_cast(glm::inverse(glm::lookAt(eye, target, camera_up(forward, up))));
}

ecs::Entity add_camera(ecs::World& world, const CameraPose& pose, const Camera& camera) {
  const ecs::Entity entity = world.create();
  world.add<ecs::LocalTransform>(entity, pose.eye, look_rotation(pose.eye, pose.target, pose.up));
  world.add<ecs::WorldTransform>(entity);
  world.add<Camera>(entity, camera);
  return entity;
}

}  // namespace sg::scene
