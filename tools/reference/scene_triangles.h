// SPDX-License-Identifier: MIT
#pragma once
// The scene's triangles in world space, as the renderer draws them: every MeshInstance's mesh
// from the MeshLibrary under its entity's WorldTransform.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "systems/scene/layers.h"
#include "systems/scene/scene.h"
#include "tools/reference/ray_scene.h"

namespace sg::reference {

// Three corners per triangle.
struct SceneTriangles {
  std::vector<glm::vec3> casters;               // instances that cast shadows (what shadow maps draw)
  std::vector<scene::LayerMask> caster_layers;  // per caster triangle: MeshInstance::shadow_layers
  std::vector<glm::vec3> surfaces;              // every instance (what the camera sees)
};

// World transforms must be up to date.
SceneTriangles scene_triangles(const scene::Scene& scene);

// The casters a light's maps draw, one RayScene per caster mask (ShadowSettings::caster_mask) of
// `masks`, the lights': the triangles on a layer of the mask.
class CasterScenes {
 public:
  CasterScenes(const SceneTriangles& triangles, std::span<const scene::LayerMask> masks);
  // The casters of `mask`, one of those given.
  const RayScene& of(scene::LayerMask mask) const;

 private:
  std::array<std::unique_ptr<RayScene>, 256> scenes_;
};

// Stops the mesh instances whose entity, or its parent (a glTF node's primitives are its
// children), has a Name containing `name` from casting shadows, in the engine's maps and in the
// reference alike: for scenes that put a visible marker mesh around a light. Returns how many.
uint32_t stop_casting(scene::Scene& scene, std::string_view name);

}  // namespace sg::reference
