// SPDX-License-Identifier: MIT
#pragma once
// glTF 2.0 import (.gltf with external or data-URI buffers, and .glb) into a Scene.
//
// What becomes what:
// - each node of the default scene (or of scene 0, or every root node when the file has no
//   scenes) -> an entity with LocalTransform (TRS, or the node matrix decomposed; shear is
//   dropped with a warning), WorldTransform and Name when named, parented like the file;
// - each triangle primitive of a node's mesh -> a child entity with MeshInstance + Material;
// - a node's perspective camera -> Camera on the node's entity (orthographic: warning, skipped;
//   an infinite far plane becomes 10,000 * znear);
// - a node's KHR_lights_punctual light -> PointLight, SpotLight or DirectionalLight with
//   FalloffMode::gltf_punctual (or the extras' falloff), plus ShadowSettings from the light's
//   extras (gltf_lights.h); a node's extras.shadowgraph.cylinder_light -> CylinderLight;
// - materials: base color factor and texture, alpha mode, double-sided, and specular and
//   shininess from extras.shadowgraph (systems/scene/README.md lists every extra read);
// - animations: each channel on a node's translation, rotation or scale -> NodeAnimation on
//   the node's entity (gltf_animations.h; animate_nodes plays them);
// - skins: drawn in the bind pose with a warning (a skinned mesh's vertices are already in
//   bind-pose model space, so its primitive entities are roots with identity transforms, as the
//   spec ignores a skinned mesh node's own transform).
//
// Validation: see gltf_source.h, gltf_preflight.h, gltf_validate.h, gltf_meshes.h and
// gltf_lights.h. Any refusal is a SceneError naming the file, the object and the problem;
// odd-but-usable input is kept, clamped where needed, and reported in Scene::warnings.
#include <string>

#include "systems/scene/scene.h"

namespace sg::scene {

// World transforms are up to date on return.
Scene load_gltf(const std::string& path);

}  // namespace sg::scene
