// SPDX-License-Identifier: MIT
#pragma once
// Step 3 of import: tinygltf parses the preflighted source into a Model. Images are decoded by
// our own callback, which refuses oversized images before decoding and always yields RGBA8.
#include <tiny_gltf.h>

#include "systems/scene/gltf_source.h"
#include "systems/scene/scene.h"

namespace sg::scene {

// Throws SceneError with tinygltf's message; tinygltf's warnings go to `scene`.
tinygltf::Model parse_gltf_model(const GltfSource& source, Scene& scene);

}  // namespace sg::scene
