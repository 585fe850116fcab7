// SPDX-License-Identifier: MIT
#pragma once
// Reads a validated accessor (gltf_validate.h) into plain numbers: any component type, any
// byteStride (interleaved or packed), normalized integers mapped to [0, 1] or [-1, 1] as the
// glTF spec says, view-less accessors as zeros, sparse substitution applied.
#include <cstddef>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace sg::scene {

// count * components values, element by element. Throws SceneError when a sparse index is
// not below the accessor's count.
std::vector<double> read_accessor(const tinygltf::Model& model, std::size_t index, const std::string& where);

}  // namespace sg::scene
