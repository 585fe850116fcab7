// SPDX-License-Identifier: MIT
#pragma once
// A loaded or built scene: the ECS world with its entities, plus the geometry and images the
// entities refer to by index, and what the loader had to say.
//
// Entities and their components:
// - every glTF node / built-in object: ecs::LocalTransform, ecs::WorldTransform (up to date
//   when the scene is returned), hierarchy through ecs::set_parent;
// - drawables: MeshInstance + Material;
// - lights: one of PointLight, SpotLight, DirectionalLight, CylinderLight, plus ShadowSettings;
// - cameras: Camera (the first one created is the scene's default view);
// - anything named in the file or by the builder: Name (for light lists and debugging).
#include <string>
#include <vector>

#include "ecs/world.h"
#include "systems/scene/mesh_library.h"
#include "systems/scene/texture_library.h"

namespace sg::scene {

struct Name {
  std::string value;
};

// A world that keeps the removal history of MeshInstance, WorldTransform and Material, which
// renderers read to notice drawables that went away (GpuScene::gather_changes).
ecs::World make_scene_world();

struct Scene {
  std::string name;  // the file path, or the built-in scene's name
  ecs::World world = make_scene_world();
  MeshLibrary meshes;
  TextureLibrary textures;
  std::vector<std::string> warnings;  // odd but usable input, each also printed to stderr
};

// Records a warning in the scene and prints it to stderr as "warning: <name>: <text>".
void warn(Scene& scene, std::string text);

}  // namespace sg::scene
