// SPDX-License-Identifier: MIT
#pragma once
// One drawable: a mesh of the scene's MeshLibrary placed by the entity's WorldTransform. The
// entity also carries a Material. Imported glTF primitives become one such entity each, a child
// of their node's entity.
#include <cstdint>

#include "systems/scene/layers.h"

namespace sg::scene {

struct MeshInstance {
  std::uint32_t mesh = 0;       // index into MeshLibrary::meshes
  bool casts_shadow = true;     // false: drawn in the lighting pass only, never into shadow maps
  bool receives_shadow = true;  // false: lit as if no light cast a shadow on it
  // The layers (layers.h) on which lights see it: a light whose light_mask shares none leaves it
  // unlit, one whose caster_mask shares none of shadow_layers draws it into no map.
  LayerMask light_layers = first_layer;
  LayerMask shadow_layers = first_layer;
};

}  // namespace sg::scene
