#pragma once
// One drawable: a mesh of the scene's MeshLibrary placed by the entity's WorldTransform. The
// entity also carries a Material. Imported glTF primitives become one such entity each, a child
// of their node's entity.
#include <cstdint>

#include "systems/scene/material.h"

namespace sg::scene {

struct MeshInstance {
  std::uint32_t mesh = 0;    // index into MeshLibrary::meshes
  bool casts_shadow = true;  // false: drawn in the lighting pass only, never into shadow maps
};

// Whether an instance with `material` (nullptr: the default, opaque) draws into shadow maps: its
// own flag says so, and its material is not transparent. Transparent (blend) surfaces cast no
// shadow yet: in the shared ShadowsSpot scene the light sits inside a transparent marker cone.
inline bool casts_shadow(const MeshInstance& instance, const Material* material) {
  return instance.casts_shadow && (material == nullptr || material->alpha_mode != AlphaMode::blend);
}

}  // namespace sg::scene
