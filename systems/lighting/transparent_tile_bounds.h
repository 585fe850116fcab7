// SPDX-License-Identifier: MIT
#pragma once
// Where transparent surfaces lie on screen, per light tile, for light culling: each transparent
// instance's world bounds, projected, widen the depth range of the tiles they cover, so that a
// tile's lights for transparent surfaces reach them (TransparentPass). Conservative: a box
// covers more than its surface does. A few transparent instances cost a few thousand tile
// visits on the CPU; no pass, no image.
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "systems/lighting/light_tiles_pass.h"
#include "systems/scene/aabb.h"

namespace sg {

// Per tile of `grid`, row by row: x the nearest depth, y the farthest (reversed depths,
// systems/gpu/camera.h) of `boxes` seen through `view_projection`; x is 0 where no box covers the
// tile. A box reaching behind the camera covers every tile, from the near plane. Writes into
// `bounds` (resized).
void transparent_tile_bounds(const glm::mat4& view_projection, LightTileGrid grid, glm::uvec2 screen,
                             std::span<const scene::Aabb> boxes, std::vector<glm::vec2>& bounds);

}  // namespace sg
