// SPDX-License-Identifier: MIT
#include "systems/shadows/light_views.h"

#include <algorithm>
#include <cassert>

#include <glm/gtc/matrix_transform.hpp>

#include "systems/scene/camera.h"

namespace sg::shadows {
namespace {

// World -> view of a camera at `position` looking along `direction`, with the scene library's
// up vector (scene::camera_up, as scene::look_rotation takes it). Straight from lookAt, not
// through the orientation's quaternion and a 4x4 inverse: gathering 100,000 lights, every one
// moving, took 10.3-10.9 ms on one thread of the 2-core VM against 14.4-14.6 (2026-12-06).
glm::mat4 look_along(glm::vec3 position, glm::vec3 direction) {
  const glm::vec3 target = position + direction;
  return glm::lookAt(position, target,
                     scene::camera_up(glm::normalize(target - position), {0.0f, 1.0f, 0.0f}));
}

// Vulkan's NDC y points down; the camera flips its projection the same way (systems/gpu/camera.cpp).
glm::mat4 flip_y(glm::mat4 projection) {
  projection[0][1] = -projection[0][1];
  projection[1][1] = -projection[1][1];
  projection[2][1] = -projection[2][1];
  projection[3][1] = -projection[3][1];
  return projection;
}

float fit_margin(const scene::Aabb& bounds) { return std::max(0.005f * glm::length(bounds.extent()), 1e-3f); }

}  // namespace

float shadow_near_plane(float range) { return std::clamp(range / 200.0f, 0.01f, 0.1f); }

LightView spot_light_view(glm::vec3 position, glm::vec3 direction, float outer_cone, float range) {
  LightView light;
  light.view = look_along(position, direction);
  light.near = shadow_near_plane(range);
  light.far = range;
  const float fov = std::min(2.0f * outer_cone, max_spot_shadow_fov);
  light.projection = flip_y(glm::perspectiveRH_ZO(fov, 1.0f, light.near, light.far));
  return light;
}

LightView directional_light_view(glm::vec3 direction, const scene::Aabb& bounds) {
  assert(!bounds.empty());
  // Any eye works for an orthographic view; one outside the box keeps near and far positive.
  const glm::vec3 eye = bounds.center() - direction * glm::length(bounds.extent());
  LightView light;
  light.view = look_along(eye, direction);
  light.orthographic = true;
  const scene::Aabb box = scene::transformed(bounds, light.view);
  const float margin = fit_margin(bounds);
  // The light looks down -Z: depth along its axis is -z.
  light.near = -box.max.z - margin;
  light.far = -box.min.z + margin;
  light.projection = flip_y(glm::orthoRH_ZO(box.min.x - margin, box.max.x + margin, box.min.y - margin,
                                            box.max.y + margin, light.near, light.far));
  return light;
}

LightView directional_slice_view(const LightView& whole, glm::vec3 centre, float half_extent, float snap) {
  LightView light = whole;
  // The lattice is fixed in the light's rotation alone, so that it stays where it is when the
  // scene's bounds (the view's origin) change. The view moves the square's centre to the axis,
  // so that the projection, symmetric, is the same bit for bit wherever the square lies.
  const glm::mat3 rotation(light.view);
  const glm::vec2 snapped = glm::round(glm::vec2(rotation * centre) / snap) * snap;
  const glm::vec2 middle = snapped + glm::vec2(light.view[3]);
  light.view = glm::translate(glm::mat4(1.0f), glm::vec3(-middle, 0.0f)) * light.view;
  light.projection =
      flip_y(glm::orthoRH_ZO(-half_extent, half_extent, -half_extent, half_extent, light.near, light.far));
  return light;
}

LightView cylinder_light_view(glm::vec3 position, glm::vec3 direction, float outer_radius,
                              const scene::Aabb& bounds) {
  LightView light;
  light.view = look_along(position, direction);
  light.orthographic = true;
  const float margin = fit_margin(bounds);
  const float farthest = bounds.empty() ? 0.0f : -scene::transformed(bounds, light.view).min.z;
  light.near = 0.0f;
  light.far = std::max(farthest, 0.0f) + margin;
  light.projection = flip_y(
      glm::orthoRH_ZO(-outer_radius, outer_radius, -outer_radius, outer_radius, light.near, light.far));
  return light;
}

CubeViews point_light_cube(glm::vec3 position, float range) {
  struct Face {
    glm::vec3 axis;
    glm::vec3 up;
  };
  static constexpr Face faces[6] = {{{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}},
                                    {{0, 1, 0}, {0, 0, 1}},  {{0, -1, 0}, {0, 0, -1}},
                                    {{0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, -1, 0}}};
  CubeViews cube;
  cube.near = shadow_near_plane(range);
  cube.far = range;
  // No y flip here: see CubeViews in the header.
  const glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, cube.near, cube.far);
  for (int f = 0; f < 6; ++f) {
    cube.view_projection[f] = projection * glm::lookAtRH(position, position + faces[f].axis, faces[f].up);
  }
  return cube;
}

std::array<glm::vec4, 6> frustum_planes(const glm::mat4& m) {
  const glm::vec4 row0(m[0][0], m[1][0], m[2][0], m[3][0]);
  const glm::vec4 row1(m[0][1], m[1][1], m[2][1], m[3][1]);
  const glm::vec4 row2(m[0][2], m[1][2], m[2][2], m[3][2]);
  const glm::vec4 row3(m[0][3], m[1][3], m[2][3], m[3][3]);
  return {row3 + row0, row3 - row0, row3 + row1, row3 - row1, row2, row3 - row2};
}

}  // namespace sg::shadows
