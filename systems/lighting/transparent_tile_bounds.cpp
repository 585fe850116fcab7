// SPDX-License-Identifier: MIT
#include "systems/lighting/transparent_tile_bounds.h"

#include <algorithm>
#include <cmath>

#include "systems/gpu/camera.h"

namespace sg {

void transparent_tile_bounds(const glm::mat4& view_projection, LightTileGrid grid, glm::uvec2 screen,
                             std::span<const scene::Aabb> boxes, std::vector<glm::vec2>& bounds) {
  bounds.assign(grid.count(), glm::vec2(0.0f, camera_near_depth));
  const auto widen = [&](glm::uvec2 first, glm::uvec2 last, float nearest, float farthest) {
    for (uint32_t y = first.y; y <= last.y; ++y) {
      for (uint32_t x = first.x; x <= last.x; ++x) {
        glm::vec2& tile = bounds[y * grid.across + x];
        tile = {std::max(tile.x, nearest), std::min(tile.y, farthest)};
      }
    }
  };
  const glm::uvec2 last_tile(grid.across - 1, grid.down - 1);
  for (const scene::Aabb& box : boxes) {
    if (box.empty()) continue;
    glm::vec2 lo(1.0f), hi(-1.0f);  // NDC
    float nearest = camera_far_depth;
    float farthest = camera_near_depth;
    bool behind = false;
    int in_front = 0;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                        (corner & 4) ? box.max.z : box.min.z);
      const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
      if (clip.w <= 0.0f) {
        behind = true;
        continue;
      }
      ++in_front;
      const glm::vec3 ndc = glm::vec3(clip) / clip.w;
      lo = glm::min(lo, glm::vec2(ndc));
      hi = glm::max(hi, glm::vec2(ndc));
      nearest = std::max(nearest, ndc.z);
      farthest = std::min(farthest, ndc.z);
    }
    if (in_front == 0) continue;
    if (behind) {  // part of it behind the camera: anywhere on screen, up to the near plane
      widen({0, 0}, last_tile, camera_near_depth, std::min(farthest, camera_near_depth));
      continue;
    }
    if (hi.x < -1.0f || hi.y < -1.0f || lo.x > 1.0f || lo.y > 1.0f) continue;  // off screen
    const auto tile_of = [&](glm::vec2 ndc) {
      const glm::vec2 pixel =
          glm::clamp((ndc * 0.5f + 0.5f) * glm::vec2(screen), glm::vec2(0.0f), glm::vec2(screen) - 1.0f);
      return glm::min(glm::uvec2(pixel) / tiles::LIGHT_TILE_SIZE, last_tile);
    };
    widen(tile_of(lo), tile_of(hi), std::min(nearest, camera_near_depth),
          std::max(farthest, camera_far_depth));
  }
}

}  // namespace sg
