// SPDX-License-Identifier: MIT
#include "systems/scene/primitive_meshes.h"

#include <cmath>
#include <vector>

#include <glm/gtc/constants.hpp>

namespace sg::scene {

std::uint32_t add_box_mesh(MeshLibrary& library) {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  for (int axis = 0; axis < 3; ++axis) {
    for (const float side : {-1.0f, 1.0f}) {
      glm::vec3 normal(0.0f);
      normal[axis] = side;
      // Two tangents with cross(u, v) == normal keep every face counter-clockwise from outside.
      const glm::vec3 u = glm::vec3(normal.z, normal.x, normal.y);  // a perpendicular axis
      const glm::vec3 v = glm::cross(normal, u);
      const auto base = static_cast<std::uint32_t>(vertices.size());
      const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (const glm::vec2& corner : corners) {
        const glm::vec3 position = 0.5f * (normal + (corner.x * 2 - 1) * u + (corner.y * 2 - 1) * v);
        vertices.push_back({position, normal, corner});
      }
      for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
    }
  }
  return add_mesh(library, "box", vertices, indices);
}

std::uint32_t add_quad_mesh(MeshLibrary& library) {
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const Vertex vertices[4] = {{{-0.5f, 0.0f, -0.5f}, up, {0.0f, 0.0f}},
                              {{-0.5f, 0.0f, 0.5f}, up, {0.0f, 1.0f}},
                              {{0.5f, 0.0f, 0.5f}, up, {1.0f, 1.0f}},
                              {{0.5f, 0.0f, -0.5f}, up, {1.0f, 0.0f}}};
  const std::uint32_t indices[6] = {0, 1, 2, 0, 2, 3};
  return add_mesh(library, "quad", vertices, indices);
}

std::uint32_t add_cylinder_mesh(MeshLibrary& library, std::uint32_t segments) {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  const float step = glm::two_pi<float>() / static_cast<float>(segments);
  // Sides: a top and a bottom vertex per segment edge, normals pointing out.
  for (std::uint32_t s = 0; s <= segments; ++s) {
    const float angle = step * static_cast<float>(s);
    const glm::vec3 out(std::cos(angle), 0.0f, -std::sin(angle));
    const float u = static_cast<float>(s) / static_cast<float>(segments);
    vertices.push_back({0.5f * out + glm::vec3(0, -0.5f, 0), out, {u, 0.0f}});
    vertices.push_back({0.5f * out + glm::vec3(0, 0.5f, 0), out, {u, 1.0f}});
  }
  for (std::uint32_t s = 0; s < segments; ++s) {
    const std::uint32_t b0 = 2 * s, t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
    for (const std::uint32_t i : {b0, b1, t1, b0, t1, t0}) indices.push_back(i);
  }
  // Caps: fans of their own vertices (flat normals).
  for (const float y : {-0.5f, 0.5f}) {
    const auto base = static_cast<std::uint32_t>(vertices.size());
    for (std::uint32_t s = 0; s < segments; ++s) {
      const float angle = step * static_cast<float>(s);
      const glm::vec2 circle(std::cos(angle), -std::sin(angle));
      vertices.push_back({{0.5f * circle.x, y, 0.5f * circle.y}, {0, y * 2, 0}, 0.5f + 0.5f * circle});
    }
    for (std::uint32_t s = 1; s + 1 < segments; ++s) {
      if (y > 0) {
        for (const std::uint32_t i : {base, base + s, base + s + 1}) indices.push_back(i);
      } else {
        for (const std::uint32_t i : {base, base + s + 1, base + s}) indices.push_back(i);
      }
    }
  }
  return add_mesh(library, "cylinder", vertices, indices);
}

}  // namespace sg::scene
