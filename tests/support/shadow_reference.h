// SPDX-License-Identifier: MIT
#pragma once
// CPU ground truth for the shadow tests: which floor points a box hides from a point or spot
// light, and which pixels of a camera image show lit or shadowed floor, by exact ray casting
// with the renderer's own camera matrices (systems/gpu/camera.h).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "systems/scene/aabb.h"
#include "systems/scene/camera.h"

namespace sg::test {

// A box as the scenes place one: the unit box mesh [-0.5, 0.5]^3 (scene::add_box_mesh) under
// `model`, its entity's WorldTransform matrix (any invertible affine matrix).
struct Box {
  glm::mat4 model{1.0f};
};

// Whether the segment from `from` to `to`, endpoints included, touches the box.
bool segment_hits_aabb(glm::vec3 from, glm::vec3 to, const scene::Aabb& box);
bool segment_hits_box(glm::vec3 from, glm::vec3 to, const Box& box);

// Whether `box` hides the light at `light_position` from `floor_point`.
bool floor_point_shadowed(glm::vec3 floor_point, glm::vec3 light_position, const Box& box);

struct Ray {
  glm::vec3 origin;     // on the camera's near plane
  glm::vec3 direction;  // unit
};

// A camera image as the renderer draws it: view_matrix(pose), projection_matrix(lens, aspect of
// `size`), Vulkan framebuffer rows (row 0 at the top).
struct CameraImage {
  scene::CameraPose pose;
  scene::Camera lens;
  glm::uvec2 size{1, 1};  // pixels
};

// The ray through the centre of pixel (x, y).
Ray pixel_ray(const CameraImage& camera, std::uint32_t x, std::uint32_t y);

// Where `ray` meets the plane y = 0 ahead of its origin; nullopt when it does not.
std::optional<glm::vec3> hit_floor(const Ray& ray);

enum class FloorPixel : std::uint8_t {
  not_floor,  // no floor there, or a box in front of it
  lit,
  shadowed,  // a box hides the light
  edge,      // only from with_edge_band: near a change of class, where any answer is right
};

struct FloorPixels {
  glm::uvec2 size{0, 0};
  std::vector<FloorPixel> pixels;  // row-major, row 0 at the top

  FloorPixel at(std::uint32_t x, std::uint32_t y) const { return pixels[y * size.x + x]; }
};

// Every pixel of `camera`, classified at its centre: the floor is y = 0 with |x| and |z| up to
// floor_half_extent; `boxes` (the occluders above it, not the floor's own slab) hide the light
// at `light_position` from floor points, and floor points from the camera.
FloorPixels classify_floor(const CameraImage& camera, float floor_half_extent, glm::vec3 light_position,
                           std::span<const Box> boxes);

// `classified` with each lit or shadowed pixel that has a pixel of another class within
// `radius` pixels (Chebyshev distance) turned into `edge`: the band where rasterization and
// filtering make the exact answer uncertain. not_floor pixels stay as they are.
FloorPixels with_edge_band(const FloorPixels& classified, int radius);

}  // namespace sg::test
