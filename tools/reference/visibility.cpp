// SPDX-License-Identifier: MIT
#include "tools/reference/visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/constants.hpp>

#include "systems/shadows/light_formulas.h"

namespace sg::reference {
namespace {

// Ray origins leave the surface by this fraction of their distance from the camera: above the
// depth buffer's error at that distance, below any gap between a caster and its receiver.
constexpr float origin_offset = 1e-3f;

// Where a shadow ray starts from a surface point, and how far it may go towards `target` (a
// point) or along `direction` (a direction light, `target` unused).
struct ShadowRay {
  glm::vec3 origin;
  float near;
};

ShadowRay start(const SurfacePoint& point, glm::vec3 eye) {
  const float offset = origin_offset * std::max(glm::length(point.position - eye), 1.0f);
  if (point.has_normal) return {point.position + point.normal * offset, 0.0f};
  return {point.position, 2.0f * offset};
}

// Whether the emitter point `target` (a positional light's) is hidden from `point`.
bool blocked_towards(const RayScene& casters, const ShadowRay& ray, glm::vec3 target) {
  const glm::vec3 offset = target - ray.origin;
  const float distance = glm::length(offset);
  if (distance <= ray.near) return false;
  return casters.occluded(ray.origin, offset / distance, ray.near, distance);
}

// Whether light travelling along `travel` (unit) is blocked before it reaches `point`, for a
// parallel light whose rays start on the plane through `plane_point` perpendicular to
// `axis` (cylinder), or anywhere (directional: `bounded` false).
bool blocked_along(const RayScene& casters, const ShadowRay& ray, glm::vec3 travel, bool bounded,
                   glm::vec3 plane_point, glm::vec3 axis) {
  float far = std::numeric_limits<float>::infinity();
  if (bounded) {
    far = glm::dot(ray.origin - plane_point, axis) / std::max(glm::dot(-travel, -axis), 1e-6f);
    if (far <= ray.near) return false;
  }
  return casters.occluded(ray.origin, -travel, ray.near, far);
}

// Two unit vectors perpendicular to unit `n` and to each other.
void basis(glm::vec3 n, glm::vec3& u, glm::vec3& v) {
  const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  u = glm::normalize(glm::cross(helper, n));
  v = glm::cross(n, u);
}

// Sample k of a `side` x `side` stratified grid on the unit disc, jittered per pixel.
glm::vec2 disc_sample(uint32_t k, uint32_t side, uint32_t x, uint32_t y) {
  const glm::vec3 jitter = shadows::glsl::cell_random(glm::uvec2(x, y), k);
  const float su = (float(k % side) + jitter.x) / float(side);
  const float sv = (float(k / side) + jitter.y) / float(side);
  const float radius = std::sqrt(su);
  const float angle = glm::two_pi<float>() * sv;
  return radius * glm::vec2(std::cos(angle), std::sin(angle));
}

template <typename PerPixel>
std::vector<float> per_pixel(const SurfacePoints& points, jobs::ThreadPool& pool, PerPixel visibility) {
  std::vector<float> out(points.points.size(), 0.0f);
  pool.run(points.height, [&](size_t row) {
    const auto y = static_cast<uint32_t>(row);
    for (uint32_t x = 0; x < points.width; ++x) {
      const size_t i = size_t{y} * points.width + x;
      if (points.points[i].valid) out[i] = visibility(points.points[i], x, y);
    }
  });
  return out;
}

}  // namespace

float hard_visible(const RayScene& casters, const SurfacePoint& point, glm::vec3 eye,
                   const ReferenceLight& light) {
  const ShadowRay ray = start(point, eye);
  bool blocked = false;
  switch (light.type) {
    case LightType::point:
    case LightType::spot: blocked = blocked_towards(casters, ray, light.position); break;
    case LightType::directional:
      blocked = blocked_along(casters, ray, light.direction, false, light.position, light.direction);
      break;
    case LightType::cylinder:
      blocked = blocked_along(casters, ray, light.direction, true, light.position, light.direction);
      break;
  }
  return blocked ? 0.0f : 1.0f;
}

float soft_visible(const RayScene& casters, const SurfacePoint& point, glm::vec3 eye,
                   const ReferenceLight& light, uint32_t samples, glm::uvec2 pixel) {
  const auto side = static_cast<uint32_t>(std::ceil(std::sqrt(float(std::max(samples, 1u)))));
  const uint32_t count = side * side;
  const bool positional = light.type == LightType::point || light.type == LightType::spot;
  // A directional emitter `light_size` wide one unit away: directions within this tangent.
  const float half_width = 0.5f * light.light_size;
  const ShadowRay ray = start(point, eye);
  const glm::vec3 axis = positional ? glm::normalize(light.position - ray.origin) : -light.direction;
  glm::vec3 u, v;
  basis(axis, u, v);
  uint32_t reached = 0;
  for (uint32_t k = 0; k < count; ++k) {
    const glm::vec2 d = disc_sample(k, side, pixel.x, pixel.y) * half_width;
    bool blocked = false;
    if (positional) {
      blocked = blocked_towards(casters, ray, light.position + d.x * u + d.y * v);
    } else {
      const glm::vec3 travel = -glm::normalize(axis + d.x * u + d.y * v);
      blocked = blocked_along(casters, ray, travel, light.type == LightType::cylinder, light.position,
                              light.direction);
    }
    reached += blocked ? 0u : 1u;
  }
  return float(reached) / float(count);
}

std::vector<float> hard_visibility(const RayScene& casters, const SurfacePoints& points,
                                   const ReferenceLight& light, jobs::ThreadPool& pool) {
  return per_pixel(points, pool, [&](const SurfacePoint& point, uint32_t, uint32_t) {
    return hard_visible(casters, point, points.eye, light);
  });
}

std::vector<float> soft_visibility(const RayScene& casters, const SurfacePoints& points,
                                   const ReferenceLight& light, uint32_t samples, jobs::ThreadPool& pool) {
  return per_pixel(points, pool, [&](const SurfacePoint& point, uint32_t x, uint32_t y) {
    return soft_visible(casters, point, points.eye, light, samples, {x, y});
  });
}

}  // namespace sg::reference
