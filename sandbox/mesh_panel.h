// SPDX-License-Identifier: MIT
#pragma once
// The Meshes panel: find a drawable by name and switch what it does for the lights: whether it
// casts and receives shadows, the layers lights see it on (systems/scene/layers.h), and its
// material's specular strength and shininess. It starts collapsed: listing a scene of many
// thousand drawables costs a frame time only when open.
#include <array>
#include <string>
#include <vector>

#include "ecs/entity.h"
#include "ecs/world.h"

namespace sg::sandbox {

// A drawable's name in lists: its own Name, else its parent's (an imported glTF node's
// primitives are its children), else "mesh N" by its MeshInstance::mesh.
std::string mesh_label(const ecs::World& world, ecs::Entity entity);

class MeshPanel {
 public:
  void draw(ecs::World& world);

 private:
  std::array<char, 64> filter_{};
  std::vector<std::pair<ecs::Entity, std::string>> listed_;
  ecs::Entity selected_ = ecs::null_entity;
};

}  // namespace sg::sandbox
