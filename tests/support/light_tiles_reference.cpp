// SPDX-License-Identifier: MIT
#include "tests/support/light_tiles_reference.h"

#include <algorithm>
#include <cstring>

#include <glm/integer.hpp>

#include "systems/gpu/camera.h"

namespace sg::test {
namespace glsl {
using namespace glm;
using uint = std::uint32_t;
#include "shaders/light_record.glsl"
#include "shaders/light_tiles.glsl"
}  // namespace glsl

static_assert(sizeof(glsl::Light) == sizeof(shadows::GpuLight));

std::vector<TileLightSets> reference_light_tiles(std::span<const float> depth, uint32_t width,
                                                 uint32_t height, const glm::mat4& view_projection,
                                                 std::span<const shadows::GpuLight> lights) {
  const uint32_t size = glsl::LIGHT_TILE_SIZE;
  const uint32_t across = (width + size - 1) / size;
  const uint32_t down = (height + size - 1) / size;
  const glm::mat4 inverse = glm::inverse(view_projection);
  std::vector<TileLightSets> tiles(across * down);
  for (uint32_t ty = 0; ty < down; ++ty) {
    for (uint32_t tx = 0; tx < across; ++tx) {
      // Reversed depths (systems/gpu/camera.h): the nearest surface has the greatest.
      float nearest = camera_far_depth, farthest = camera_near_depth;
      for (uint32_t y = ty * size; y < std::min(height, (ty + 1) * size); ++y) {
        for (uint32_t x = tx * size; x < std::min(width, (tx + 1) * size); ++x) {
          const float d = depth[y * width + x];
          if (d <= camera_far_depth) continue;
          nearest = std::max(nearest, d);
          farthest = std::min(farthest, d);
        }
      }
      if (nearest <= camera_far_depth) continue;  // background only: no lights
      const glm::vec2 texel = 2.0f / glm::vec2(width, height);
      const glm::vec2 ndc_min = glm::vec2(tx * size, ty * size) * texel - 1.0f;
      const glm::vec2 ndc_max =
          glm::min(glm::vec2((tx + 1) * size, (ty + 1) * size) * texel - 1.0f, glm::vec2(1.0f));
      const glsl::TileVolume volume = glsl::tile_volume(inverse, ndc_min, ndc_max, nearest, farthest);
      // The depth slices a surface may be in (`may`), and those it is in whichever way the GPU
      // rounds its depth (`must`).
      uint32_t may_slices = 0, must_slices = 0;
      const float span = volume.shells.w - volume.shells.z;
      const float rounding =
          span > 0.0f ? glsl::depth_slice_rounding(volume) * glsl::DEPTH_SLICES / span : 0.0f;
      for (uint32_t y = ty * size; y < std::min(height, (ty + 1) * size); ++y) {
        for (uint32_t x = tx * size; x < std::min(width, (tx + 1) * size); ++x) {
          const float d = depth[y * width + x];
          if (d <= camera_far_depth) continue;
          const float position = glsl::depth_slice_position(volume, d);
          const uint32_t first = glsl::depth_slice_bit(position - rounding);
          const uint32_t last = glsl::depth_slice_bit(position + rounding);
          may_slices |= glsl::depth_slices_between(first, last);
          if (first == last) must_slices |= first;
        }
      }
      // The GPU's rounding may differ: lights within a hair of the volume's bounds may go either way.
      const float hair = 1e-3f * volume.sphere.w + 1e-4f;
      const glm::vec4 inner(glm::vec3(volume.sphere), std::max(volume.sphere.w - hair, 0.0f));
      const glm::vec4 outer(glm::vec3(volume.sphere), volume.sphere.w + hair);
      TileLightSets& sets = tiles[ty * across + tx];
      for (uint32_t i = 0; i < lights.size(); ++i) {
        glsl::Light light;
        std::memcpy(&light, &lights[i], sizeof(light));
        // A light whose range or cone is tested against the slices, where the tile has no slice
        // it must be in, may be dropped (light_reaches_tile keeps every light where it knows no
        // slices); the others reach every slice.
        const uint32_t must_reach = glsl::depth_slices_in_reach(light, volume, -hair);
        const uint32_t must_reached = must_slices & must_reach;
        const uint32_t may_reached = may_slices & glsl::depth_slices_in_reach(light, volume, hair);
        const bool must_slice =
            (must_reach == ~0u && light.info.x != glsl::LIGHT_SPOT) ||
            (must_reached != 0 && !glsl::spot_cone_misses_tile(light, volume, must_reached, -hair));
        if (glsl::light_reaches_sphere(light, inner) &&
            glsl::light_range_meets_tile_cone(light, volume, -hair) && must_slice) {
          sets.must.push_back(i);
        }
        if (glsl::light_reaches_sphere(light, outer) &&
            glsl::light_range_meets_tile_cone(light, volume, hair) && may_reached != 0 &&
            !glsl::spot_cone_misses_tile(light, volume, may_reached, hair)) {
          sets.may.push_back(i);
        }
      }
    }
  }
  return tiles;
}

}  // namespace sg::test
