// SPDX-License-Identifier: MIT
#pragma once
// Step 4 of import: the structural rules tinygltf does not enforce, checked on the parsed Model
// before any accessor is read. After it passes, every index the importer follows points at an
// existing object and every accessor's bytes lie inside its buffer view:
// - accessors: count >= 1; byteOffset + (count - 1) * stride + element size <= the view's
//   byteLength; byteStride >= element size; implicit (view-less) accessors capped in size;
//   sparse indices and values inside their views, sparse count <= count, unsigned indices;
// - meshes: attribute and index accessors exist, attributes of a primitive agree in count,
//   POSITION/NORMAL are VEC3 and TEXCOORD_0 VEC2, indices are scalar unsigned integers;
// - nodes: mesh, camera, skin and children exist; each node has at most one parent; no cycles;
//   no deeper than gltf_limits::max_node_depth; transform arrays of the right length;
// - scenes reference existing nodes; materials existing textures; textures existing images;
// - perspective cameras: yfov > 0, znear > 0, zfar > znear when given.
// Numbers in the JSON are finite by construction: JSON has no NaN or infinity, and an
// overflowing literal such as 1e999 is a parse error (gltf_source.h).
// Index values against vertex counts and finite vertex data are checked while reading
// (gltf_meshes.h), since that needs the data itself.
#include <string>

#include <tiny_gltf.h>

namespace sg::scene {

// Throws SceneError("<where>", "<object>", ...) for the first rule broken.
void validate_gltf_model(const tinygltf::Model& model, const std::string& where);

}  // namespace sg::scene
