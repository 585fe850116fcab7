// SPDX-License-Identifier: MIT
#pragma once
// Step 6 of import: images into the TextureLibrary (texture i of the library is glTF image i)
// and glTF materials into Material values. Only the base color (factor and texture) maps to
// the engine's Blinn model; kS and the shininess keep Material's defaults. Samplers are
// ignored (the renderer samples with repeat and linear filtering).
#include <vector>

#include <tiny_gltf.h>

#include "systems/scene/material.h"
#include "systems/scene/scene.h"

namespace sg::scene {

void import_textures(const tinygltf::Model& model, Scene& scene);

// One Material per glTF material, in order. Factors outside [0, 1] are clamped with a warning;
// a texture whose image could not be decoded falls back to no texture with a warning.
std::vector<Material> import_materials(const tinygltf::Model& model, Scene& scene);

}  // namespace sg::scene
