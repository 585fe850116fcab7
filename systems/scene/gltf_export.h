// SPDX-License-Identifier: MIT
#pragma once
// glTF 2.0 export of a Scene, so that edits made in the sandbox go back into a file other tools
// open and this engine loads to the same frame (load_gltf):
// - every entity with a LocalTransform -> a node (TRS, Name, parented as in the world); a
//   drawable's mesh and material -> a mesh of one triangle primitive (POSITION, NORMAL,
//   TEXCOORD_0, 32-bit indices) and a material (base color factor and texture, alpha mode and
//   cutoff, double-sided; specular and shininess in extras.shadowgraph); a drawable that casts no
//   shadow says extras.casts_shadow false, one that receives none extras.receives_shadow false;
// - point, spot and directional lights -> KHR_lights_punctual with their shadow settings and
//   falloff in extras.shadowgraph; cylinder lights, which glTF has no type for, ->
//   extras.shadowgraph.cylinder_light on their node;
// - cameras -> perspective cameras; `view`, when given, is written as the first camera, so the
//   file opens where the user left it;
// - textures -> PNG images; the buffer (and images) embedded in a .gltf as data URIs, or in a
//   .glb's binary chunk, by the path's extension.
// Not written: animations (node animations, the built-in scenes' motions), which the scene keeps
// as components the file cannot hold; the export says how many entities carried them.
#include <optional>
#include <string>

#include "systems/scene/camera.h"
#include "systems/scene/scene.h"

namespace sg::scene {

struct ExportView {
  CameraPose pose;
  Camera lens;
};

struct ExportReport {
  std::size_t nodes = 0;
  std::size_t meshes = 0;
  std::size_t lights = 0;
  std::size_t animated_entities = 0;  // whose motion the file does not keep
};

// Throws SceneError naming the path when it cannot be written.
ExportReport export_gltf(const Scene& scene, const std::optional<ExportView>& view, const std::string& path);

}  // namespace sg::scene
