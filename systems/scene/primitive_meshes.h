// SPDX-License-Identifier: MIT
#pragma once
// Unit primitives the built-in scenes instance: each is added to a MeshLibrary once and
// placed by LocalTransform scale, so a wall, a crate and a table top share one box mesh.
#include <cstdint>

#include "systems/scene/mesh_library.h"

namespace sg::scene {

// The cube [-0.5, 0.5]^3 (size 1), 24 vertices with face normals and per-face uvs, 12
// triangles counter-clockwise seen from outside.
std::uint32_t add_box_mesh(MeshLibrary& library);

// A closed cylinder of diameter 1 and height 1 centred on the origin, axis +Y, with `segments`
// sides (>= 3): 2 * segments side triangles + 2 * (segments - 2) cap triangles.
std::uint32_t add_cylinder_mesh(MeshLibrary& library, std::uint32_t segments);

// A unit square in the XZ plane, [-0.5, 0.5]^2, facing +Y (counter-clockwise seen from above),
// uv (x + 0.5, z + 0.5): a card for cut-outs and panes.
std::uint32_t add_quad_mesh(MeshLibrary& library);

}  // namespace sg::scene
