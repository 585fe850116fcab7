// SPDX-License-Identifier: MIT
#pragma once
// Step 2 of import, on the raw JSON before tinygltf reads it: every size tinygltf would
// allocate or read from is compared with the data that exists, and required extensions are
// checked. After this, tinygltf can load the file without over-reading or over-allocating:
// - buffers: byteLength <= the bytes available (BIN chunk, data URI payload, external file);
//   external files must exist;
// - bufferViews: inside their buffer (tinygltf decodes images from views without checking);
// - images: external files exist and are within the file size limit;
// - extensionsRequired: only the ones the importer implements.
#include "systems/scene/gltf_source.h"

namespace sg::scene {

// Throws SceneError naming the file, the object and the problem.
void preflight_gltf(const GltfSource& source);

}  // namespace sg::scene
