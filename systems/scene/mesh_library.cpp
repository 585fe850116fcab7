// SPDX-License-Identifier: MIT
#include "systems/scene/mesh_library.h"

#include <utility>

namespace sg::scene {

std::uint32_t add_mesh(MeshLibrary& library, std::string name, std::span<const Vertex> vertices,
                       std::span<const std::uint32_t> indices) {
  MeshRange range;
  range.name = std::move(name);
  range.first_index = static_cast<std::uint32_t>(library.indices.size());
  range.index_count = static_cast<std::uint32_t>(indices.size());
  range.vertex_offset = static_cast<std::uint32_t>(library.vertices.size());
  range.vertex_count = static_cast<std::uint32_t>(vertices.size());
  for (const Vertex& vertex : vertices) grow(range.bounds, vertex.position);
  library.vertices.insert(library.vertices.end(), vertices.begin(), vertices.end());
  library.indices.insert(library.indices.end(), indices.begin(), indices.end());
  library.meshes.push_back(std::move(range));
  return static_cast<std::uint32_t>(library.meshes.size() - 1);
}

void make_flat_normals(std::vector<Vertex>& vertices, std::vector<std::uint32_t>& indices) {
  std::vector<Vertex> unwelded;
  unwelded.reserve(indices.size());
  for (std::size_t first = 0; first + 2 < indices.size(); first += 3) {
    const Vertex corners[3] = {vertices[indices[first]], vertices[indices[first + 1]],
                               vertices[indices[first + 2]]};
    const glm::vec3 cross =
        glm::cross(corners[1].position - corners[0].position, corners[2].position - corners[0].position);
    const float length = glm::length(cross);
    const glm::vec3 normal = length > 0.0f ? cross / length : glm::vec3(0.0f, 1.0f, 0.0f);
    for (Vertex corner : corners) {
      corner.normal = normal;
      unwelded.push_back(corner);
    }
  }
  vertices = std::move(unwelded);
  indices.resize(vertices.size());
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
}

}  // namespace sg::scene
