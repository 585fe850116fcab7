// SPDX-License-Identifier: MIT
#include "systems/shadows/cascades.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace sg::shadows {
namespace {

// The distances from the eye [near, far] the scene's box spans, within the camera's planes and
// rounded out to powers of two: distances, not depths, so that turning the camera changes
// nothing; powers of two, so that moving it changes the slices in steps, not every frame. Empty
// (near >= far) when the box lies wholly beyond the far plane.
glm::vec2 scene_distances(const scene::Aabb& bounds, const CascadeCamera& camera) {
  const glm::vec3 nearest_point = glm::clamp(camera.eye, bounds.min, bounds.max);
  const glm::vec3 farthest_corner =
      glm::max(glm::abs(camera.eye - bounds.min), glm::abs(camera.eye - bounds.max));
  const float nearest = std::max(glm::length(camera.eye - nearest_point), camera.near);
  const float near = std::max(camera.near, std::exp2(std::floor(std::log2(nearest))));
  const float far = std::min(camera.far, std::exp2(std::ceil(std::log2(glm::length(farthest_corner)))));
  return {near, far};
}

float split(float near, float far, uint32_t k, uint32_t count) {
  const float t = float(k) / float(count);
  return cascade_log_weight * near * std::pow(far / near, t) +
         (1.0f - cascade_log_weight) * (near + (far - near) * t);
}

// The sphere around the view frustum's slice between depths a < b: its centre's depth and radius.
// `spread` is the tangent of the angle from the axis to the frustum's corner edges.
glm::vec2 slice_sphere(float a, float b, float spread) {
  const float k2 = spread * spread;
  const float centre = std::min(0.5f * (a + b) * (1.0f + k2), b);
  const float to_near = std::hypot(centre - a, a * spread);
  const float to_far = std::hypot(b - centre, b * spread);
  return {centre, std::max(to_near, to_far)};
}

}  // namespace

CascadeCamera cascade_camera(const scene::CameraPose& pose, const scene::Camera& lens, float aspect) {
  CascadeCamera camera;
  camera.eye = pose.eye;
  camera.forward = glm::normalize(pose.target - pose.eye);
  camera.yfov = lens.yfov;
  camera.aspect = lens.aspect > 0.0f ? lens.aspect : aspect;
  camera.near = lens.znear;
  camera.far = lens.zfar;
  return camera;
}

CascadeFit fit_cascades(glm::vec3 direction, const scene::Aabb& bounds, const CascadeCamera& camera,
                        uint32_t most) {
  assert(!bounds.empty() && most >= 1 && most <= max_cascades);
  CascadeFit fit;
  const LightView whole = directional_light_view(direction, bounds);
  const glm::vec2 depths = scene_distances(bounds, camera);
  fit.splits[0] = depths.x;
  fit.splits[1] = std::max(depths.x, depths.y);
  fit.views[0] = whole;
  if (most == 1 || depths.x >= depths.y) return fit;

  // The whole scene's map is this wide, as a square of its area; a slice's map at least half
  // that wide gains too little.
  const float whole_width = 2.0f / std::sqrt(std::abs(whole.projection[0][0] * whole.projection[1][1]));
  const float spread = std::tan(0.5f * camera.yfov) * std::sqrt(1.0f + camera.aspect * camera.aspect);
  // The square holds the slice's sphere wherever the snapped centre falls, cascade_edge_uv
  // inside its edge: r + snap R + 2 edge R <= R.
  const float widen = 1.0f / (1.0f - cascade_snap_fraction - 2.0f * cascade_edge_uv);
  for (uint32_t k = 0; k < most; ++k) {
    const float a = split(depths.x, depths.y, k, most);
    const float b = split(depths.x, depths.y, k + 1, most);
    const glm::vec2 sphere = slice_sphere(a, b, spread);
    const float half_extent = sphere.y * widen;
    fit.splits[k] = a;
    fit.splits[k + 1] = b;
    fit.count = k + 1;
    if (4.0f * half_extent >= whole_width) {
      fit.views[k] = whole;
      fit.splits[k + 1] = depths.y;
      break;
    }
    const glm::vec3 centre = camera.eye + camera.forward * sphere.x;
    fit.views[k] =
        directional_slice_view(whole, centre, half_extent, 2.0f * half_extent * cascade_snap_fraction);
  }
  return fit;
}

}  // namespace sg::shadows
