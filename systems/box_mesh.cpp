#include "systems/box_mesh.h"

namespace sg {

BoxMesh make_unit_box() {
  BoxMesh mesh{};
  // Each face: its normal n and two tangents u, v with cross(u, v) = n, so the corners
  // c = n + su*u + sv*v walk counter-clockwise seen from outside.
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int face = 0; face < 6; ++face) {
    const glm::vec3 n = normals[face];
    const glm::vec3 u = glm::abs(n.y) > 0.5f ? glm::vec3(0, 0, n.y) : glm::vec3(-n.z, 0, n.x);
    const glm::vec3 v = glm::cross(n, u);
    const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int c = 0; c < 4; ++c) {
      mesh.vertices[face * 4 + c] = {n + corners[c][0] * u + corners[c][1] * v, n};
    }
    const uint16_t base = static_cast<uint16_t>(face * 4);
    const uint16_t quad[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; ++i) mesh.indices[face * 6 + i] = base + quad[i];
  }
  return mesh;
}

}  // namespace sg
