// SPDX-License-Identifier: MIT
#include "systems/scene/scene.h"

#include <cstdio>
#include <utility>

#include "ecs/transform.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_instance.h"

namespace sg::scene {

ecs::World make_scene_world() {
  ecs::World world;
  world.keep_removals<MeshInstance, ecs::WorldTransform, Material>();
  return world;
}

void warn(Scene& scene, std::string text) {
  std::fprintf(stderr, "warning: %s: %s\n", scene.name.c_str(), text.c_str());
  scene.warnings.push_back(std::move(text));
}

}  // namespace sg::scene
