// SPDX-License-Identifier: MIT
#pragma once
// The scene's triangles in world space, as the renderer draws them: every MeshInstance's mesh
// from the MeshLibrary under its entity's WorldTransform.
#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "systems/scene/scene.h"

namespace sg::reference {

// Three corners per triangle.
struct SceneTriangles {
  std::vector<glm::vec3> casters;   // instances that cast shadows (what shadow maps draw)
  std::vector<glm::vec3> surfaces;  // every instance (what the camera sees)
};

// World transforms must be up to date.
SceneTriangles scene_triangles(const scene::Scene& scene);

// Stops the mesh instances whose entity, or its parent (a glTF node's primitives are its
// children), has a Name containing `name` from casting shadows, in the engine's maps and in the
// reference alike: for scenes that put a visible marker mesh around a light. Returns how many.
uint32_t stop_casting(scene::Scene& scene, std::string_view name);

}  // namespace sg::reference
