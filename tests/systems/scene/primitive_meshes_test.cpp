// SPDX-License-Identifier: MIT
// The built-in primitives: closed, outward-facing, with the documented sizes.
#include <gtest/gtest.h>

#include "systems/scene/primitive_meshes.h"

namespace sg::scene {
namespace {

// Every triangle's geometric normal agrees with its vertex normals and points away from the
// centre (both primitives are convex and centred on the origin).
void expect_outward_triangles(const MeshLibrary& library, std::uint32_t mesh) {
  const MeshRange& range = library.meshes[mesh];
  for (std::uint32_t t = 0; t < range.index_count; t += 3) {
    const Vertex* v[3];
    for (int c = 0; c < 3; ++c) {
      v[c] = &library.vertices[range.vertex_offset + library.indices[range.first_index + t + c]];
    }
    const glm::vec3 face = glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
    const glm::vec3 centroid = (v[0]->position + v[1]->position + v[2]->position) / 3.0f;
    EXPECT_GT(glm::dot(face, centroid), 0.0f) << range.name << " triangle " << t / 3;
    EXPECT_GT(glm::dot(face, v[0]->normal), 0.0f) << range.name << " triangle " << t / 3;
  }
}

TEST(PrimitiveMeshes, BoxIsAUnitCubeOfTwelveOutwardTriangles) {
  MeshLibrary library;
  const std::uint32_t box = add_box_mesh(library);
  EXPECT_EQ(triangle_count(library.meshes[box]), 12u);
  EXPECT_EQ(library.meshes[box].bounds.min, glm::vec3(-0.5f));
  EXPECT_EQ(library.meshes[box].bounds.max, glm::vec3(0.5f));
  expect_outward_triangles(library, box);
}

TEST(PrimitiveMeshes, CylinderTriangleCountAndOrientation) {
  MeshLibrary library;
  add_box_mesh(library);  // the cylinder's indices stay relative to its own vertices
  const std::uint32_t cylinder = add_cylinder_mesh(library, 16);
  EXPECT_EQ(triangle_count(library.meshes[cylinder]), 2u * 16 + 2u * 14);
  EXPECT_EQ(library.meshes[cylinder].vertex_offset, 24u);
  EXPECT_NEAR(library.meshes[cylinder].bounds.max.y, 0.5f, 1e-6f);
  EXPECT_NEAR(library.meshes[cylinder].bounds.max.x, 0.5f, 1e-6f);
  expect_outward_triangles(library, cylinder);
}

TEST(PrimitiveMeshes, QuadFacesUpWithUvAcrossIt) {
  MeshLibrary library;
  const std::uint32_t quad = add_quad_mesh(library);
  EXPECT_EQ(triangle_count(library.meshes[quad]), 2u);
  for (std::uint32_t t = 0; t < 6; t += 3) {
    const Vertex* v[3];
    for (int c = 0; c < 3; ++c) v[c] = &library.vertices[library.indices[t + c]];
    const glm::vec3 face = glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
    EXPECT_GT(face.y, 0.0f) << "counter-clockwise seen from above";
  }
  for (const Vertex& v : library.vertices) {
    EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(v.uv, glm::vec2(v.position.x + 0.5f, v.position.z + 0.5f));
  }
}

}  // namespace
}  // namespace sg::scene
