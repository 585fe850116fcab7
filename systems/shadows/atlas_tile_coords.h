// SPDX-License-Identifier: MIT
#pragma once
// Where an atlas tile is, in the coordinates each side uses: uv of its layer for the receivers
// (the light record), and the layer's clip space for the shadow passes, which draw a view into
// its tile by scaling and offsetting the view's clip xy (shaders/shadow_batch.vert).
#include <cstdint>

#include <glm/glm.hpp>

#include "systems/shadows/shadow_atlas_planner.h"

namespace sg::shadows {

// xy: the tile's top-left corner, zw: its size, in uv of a page of `page_size` texels.
inline glm::vec4 tile_uv_rect(const AtlasTile& tile, uint32_t page_size) {
  const float texel = 1.0f / float(page_size);
  return {float(tile.x) * texel, float(tile.y) * texel, float(tile.size) * texel, float(tile.size) * texel};
}

// A view's clip xy -> the page's: xy scale, zw offset (multiplied by w), so that the view's NDC
// square [-1, 1]^2 lands exactly on the tile.
inline glm::vec4 tile_clip_transform(const AtlasTile& tile, uint32_t page_size) {
  const float page = float(page_size);
  const float scale = float(tile.size) / page;
  return {scale, scale, -1.0f + (2.0f * float(tile.x) + float(tile.size)) / page,
          -1.0f + (2.0f * float(tile.y) + float(tile.size)) / page};
}

}  // namespace sg::shadows
