// SPDX-License-Identifier: MIT
#include "tests/support/shadow_reference.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "systems/gpu/camera.h"

namespace sg::test {

bool segment_hits_aabb(glm::vec3 from, glm::vec3 to, const scene::Aabb& box) {
  if (box.empty()) return false;
  // Slabs: clip the segment's parameter range [0, 1] to each axis's [min, max].
  const glm::vec3 delta = to - from;
  float enter = 0.0f, exit = 1.0f;
  for (int axis = 0; axis < 3; ++axis) {
    if (delta[axis] == 0.0f) {
      if (from[axis] < box.min[axis] || from[axis] > box.max[axis]) return false;
      continue;
    }
    float t0 = (box.min[axis] - from[axis]) / delta[axis];
    float t1 = (box.max[axis] - from[axis]) / delta[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    exit = std::min(exit, t1);
    if (enter > exit) return false;
  }
  return true;
}

bool segment_hits_box(glm::vec3 from, glm::vec3 to, const Box& box) {
  // An affine map keeps a segment a segment, with the same parameters: test in the box's space.
  const glm::mat4 to_local = glm::inverse(box.model);
  const scene::Aabb unit{glm::vec3(-0.5f), glm::vec3(0.5f)};
  return segment_hits_aabb(glm::vec3(to_local * glm::vec4(from, 1.0f)),
                           glm::vec3(to_local * glm::vec4(to, 1.0f)), unit);
}

bool floor_point_shadowed(glm::vec3 floor_point, glm::vec3 light_position, const Box& box) {
  return segment_hits_box(floor_point, light_position, box);
}

Ray pixel_ray(const CameraImage& camera, std::uint32_t x, std::uint32_t y) {
  const float aspect = float(camera.size.x) / float(camera.size.y);
  // In double: the near and far planes are far apart, and the inverse magnifies rounding.
  const glm::dmat4 inverse_view_projection =
      glm::inverse(glm::dmat4(projection_matrix(camera.lens, aspect) * view_matrix(camera.pose)));
  const glm::dvec2 ndc((x + 0.5) / camera.size.x * 2.0 - 1.0, (y + 0.5) / camera.size.y * 2.0 - 1.0);
  const glm::dvec4 near_point = inverse_view_projection * glm::dvec4(ndc, camera_near_depth, 1.0);
  const glm::dvec4 far_point = inverse_view_projection * glm::dvec4(ndc, camera_far_depth, 1.0);
  const glm::dvec3 origin = glm::dvec3(near_point) / near_point.w;
  const glm::dvec3 direction = glm::normalize(glm::dvec3(far_point) / far_point.w - origin);
  return {glm::vec3(origin), glm::vec3(direction)};
}

std::optional<glm::vec3> hit_floor(const Ray& ray) {
  if (ray.direction.y == 0.0f) return std::nullopt;
  const float t = -ray.origin.y / ray.direction.y;
  if (t < 0.0f) return std::nullopt;
  glm::vec3 point = ray.origin + t * ray.direction;
  point.y = 0.0f;
  return point;
}

FloorPixels classify_floor(const CameraImage& camera, float floor_half_extent, glm::vec3 light_position,
                           std::span<const Box> boxes) {
  FloorPixels result{camera.size, std::vector<FloorPixel>(camera.size.x * camera.size.y)};
  for (std::uint32_t y = 0; y < camera.size.y; ++y) {
    for (std::uint32_t x = 0; x < camera.size.x; ++x) {
      const Ray ray = pixel_ray(camera, x, y);
      const std::optional<glm::vec3> point = hit_floor(ray);
      FloorPixel& pixel = result.pixels[y * camera.size.x + x];
      pixel = FloorPixel::not_floor;
      if (!point || std::abs(point->x) > floor_half_extent || std::abs(point->z) > floor_half_extent) {
        continue;
      }
      const auto hides = [&](glm::vec3 from, glm::vec3 to) {
        return std::any_of(boxes.begin(), boxes.end(),
                           [&](const Box& box) { return segment_hits_box(from, to, box); });
      };
      if (hides(ray.origin, *point)) continue;
      pixel = hides(*point, light_position) ? FloorPixel::shadowed : FloorPixel::lit;
    }
  }
  return result;
}

FloorPixels with_edge_band(const FloorPixels& classified, int radius) {
  FloorPixels banded = classified;
  const int width = int(classified.size.x), height = int(classified.size.y);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const FloorPixel own = classified.at(x, y);
      if (own == FloorPixel::not_floor) continue;
      bool near_change = false;
      for (int ny = std::max(y - radius, 0); ny <= std::min(y + radius, height - 1); ++ny) {
        for (int nx = std::max(x - radius, 0); nx <= std::min(x + radius, width - 1); ++nx) {
          near_change = near_change || classified.at(nx, ny) != own;
        }
      }
      if (near_change) banded.pixels[y * width + x] = FloorPixel::edge;
    }
  }
  return banded;
}

}  // namespace sg::test
