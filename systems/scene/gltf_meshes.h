// SPDX-License-Identifier: MIT
#pragma once
// Step 5 of import: glTF meshes into the MeshLibrary, one library mesh per triangle primitive.
// Checks what needs the data: every index below the vertex count, index (or, without
// indices, vertex) count a multiple of 3, finite positions, normals and texture coordinates.
// Non-triangle primitives and primitives without POSITION are skipped with a warning; missing
// normals are generated flat; morph targets are ignored with a warning.
#include <cstdint>
#include <vector>

#include <tiny_gltf.h>

#include "systems/scene/scene.h"

namespace sg::scene {

struct ImportedPrimitive {
  std::uint32_t mesh = 0;  // into scene.meshes
  int material = -1;       // glTF material index; -1 for the default material
};

// For each glTF mesh, its imported primitives (skipped ones are absent). Throws SceneError.
std::vector<std::vector<ImportedPrimitive>> import_meshes(const tinygltf::Model& model, Scene& scene);

}  // namespace sg::scene
