// SPDX-License-Identifier: MIT
#pragma once
// CPU geometry shared by every instance of a mesh. All meshes live in two flat arrays, so the
// renderer uploads one vertex buffer and one index buffer and draws mesh m with
// (index_count, first_index, vertex_offset) — the layout multi-draw indirect wants.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "systems/scene/aabb.h"

namespace sg::scene {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;  // unit length
  glm::vec2 uv;
};

struct MeshRange {
  std::string name;
  std::uint32_t first_index = 0;    // into MeshLibrary::indices
  std::uint32_t index_count = 0;    // a multiple of 3: triangle lists only
  std::uint32_t vertex_offset = 0;  // added to each index (indices are relative to the mesh)
  std::uint32_t vertex_count = 0;
  Aabb bounds;  // in the mesh's own space
};

struct MeshLibrary {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  std::vector<MeshRange> meshes;
};

// Appends a triangle-list mesh and returns its index in `library.meshes`. Indices are relative
// to `vertices` and must all be < vertices.size() (the caller has checked; see gltf_meshes.cpp).
std::uint32_t add_mesh(MeshLibrary& library, std::string name, std::span<const Vertex> vertices,
                       std::span<const std::uint32_t> indices);

// Sets every vertex normal to its triangle's face normal. Flat shading needs vertices that
// are not shared between triangles, so the mesh is first unwelded: the result has one vertex per
// index and indices 0, 1, 2, ... Degenerate triangles get +Y rather than NaN.
void make_flat_normals(std::vector<Vertex>& vertices, std::vector<std::uint32_t>& indices);

inline std::uint64_t triangle_count(const MeshRange& mesh) { return mesh.index_count / 3; }

}  // namespace sg::scene
