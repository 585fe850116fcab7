// SPDX-License-Identifier: MIT
#pragma once
// The surface points a frame shows: each pixel's depth taken back to world space with the
// renderer's own camera matrices (systems/gpu/camera.h), so that the reference tests visibility from
// exactly the points the engine shaded.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "ecs/jobs/thread_pool.h"
#include "rendergraph/device/readback.h"
#include "systems/scene/camera.h"
#include "tools/reference/ray_scene.h"

namespace sg::reference {

struct SurfacePoint {
  glm::vec3 position{0.0f};
  // The unit geometric normal facing the camera, from the triangle the pixel's camera ray hits.
  glm::vec3 normal{0.0f};
  // Far from the camera ray's first hit (a silhouette pixel whose depth is another triangle's),
  // rays start from the position without a normal offset.
  bool has_normal = false;
  bool valid = false;  // false: background (depth 1)
};

struct SurfacePoints {
  uint32_t width = 0;
  uint32_t height = 0;
  glm::vec3 eye{0.0f};               // the camera's position
  std::vector<SurfacePoint> points;  // row-major, row 0 at the top
};

// Maps Vulkan clip space of a `width` x `height` frame back to world space.
glm::mat4 clip_to_world(const scene::CameraPose& pose, const scene::Camera& lens, uint32_t width,
                        uint32_t height);
// World position of pixel (x, y)'s centre at `depth` (D32, 0 near .. 1 far).
glm::vec3 unproject(const glm::mat4& clip_to_world, uint32_t width, uint32_t height, uint32_t x, uint32_t y,
                    float depth);

// Every pixel of `depth` as a surface point; normals from rays cast against `surfaces`.
SurfacePoints surface_points(const vk::DepthImage& depth, const scene::CameraPose& pose,
                             const scene::Camera& lens, const RayScene& surfaces, jobs::ThreadPool& pool);

}  // namespace sg::reference
