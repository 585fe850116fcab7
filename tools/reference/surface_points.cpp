// SPDX-License-Identifier: MIT
#include "tools/reference/surface_points.h"

#include <cmath>
#include <optional>

#include "systems/gpu/camera.h"

namespace sg::reference {
namespace {

// A depth-buffer point further than this from its camera ray's hit (relative to the distance
// from the camera) belongs to another triangle: the pixel centre and the rasterized sample
// disagree at a silhouette.
constexpr float same_surface_tolerance = 1e-3f;

}  // namespace

glm::mat4 clip_to_world(const scene::CameraPose& pose, const scene::Camera& lens, uint32_t width,
                        uint32_t height) {
  return glm::inverse(projection_matrix(lens, float(width) / float(height)) * view_matrix(pose));
}

glm::vec3 unproject(const glm::mat4& clip_to_world, uint32_t width, uint32_t height, uint32_t x, uint32_t y,
                    float depth) {
  const glm::vec4 ndc{2.0f * (float(x) + 0.5f) / float(width) - 1.0f,
                      2.0f * (float(y) + 0.5f) / float(height) - 1.0f, depth, 1.0f};
  const glm::vec4 world = clip_to_world * ndc;
  return glm::vec3(world) / world.w;
}

SurfacePoints surface_points(const vk::DepthImage& depth, const scene::CameraPose& pose,
                             const scene::Camera& lens, const RayScene& surfaces, jobs::ThreadPool& pool) {
  const glm::mat4 to_world = clip_to_world(pose, lens, depth.width, depth.height);
  SurfacePoints out{depth.width, depth.height, pose.eye,
                    std::vector<SurfacePoint>(size_t{depth.width} * depth.height)};
  pool.run(depth.height, [&](size_t row) {
    const auto y = static_cast<uint32_t>(row);
    for (uint32_t x = 0; x < depth.width; ++x) {
      const float d = depth.at(x, y);
      if (d <= camera_far_depth) continue;  // cleared: nothing drawn there
      SurfacePoint& point = out.points[size_t{y} * depth.width + x];
      point.valid = true;
      point.position = unproject(to_world, depth.width, depth.height, x, y, d);
      const glm::vec3 offset = point.position - pose.eye;
      const float distance = glm::length(offset);
      if (const std::optional<RayHit> hit = surfaces.intersect(pose.eye, offset / distance)) {
        point.has_normal = std::abs(hit->distance - distance) <= same_surface_tolerance * distance;
        point.normal = hit->normal;
      }
    }
  });
  return out;
}

}  // namespace sg::reference
