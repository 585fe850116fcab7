#pragma once
// A unit cube ([-1, 1]^3) with per-face normals: the one mesh the built-in scenes instance
// for floors, walls, pillars and boxes.
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace sg {

struct MeshVertex {
  glm::vec3 position;
  glm::vec3 normal;
};

struct BoxMesh {
  std::array<MeshVertex, 24> vertices;
  std::array<uint16_t, 36> indices;  // counter-clockwise seen from outside
};

BoxMesh make_unit_box();

}  // namespace sg
