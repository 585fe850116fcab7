#pragma once
// The scene's triangles in world space, as the renderer draws them: every MeshInstance's mesh
// from the MeshLibrary under its entity's WorldTransform.
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

}  // namespace sg::reference
