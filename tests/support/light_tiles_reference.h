// SPDX-License-Identifier: MIT
#pragma once
// A CPU reference for tiled light culling (shaders/light_tiles.comp): the same tile bounds and
// light tests, compiled as C++ from shaders/light_tiles.glsl, run brute force over every tile
// and light. A light within a hair of a tile's bound may fall either way on two processors, so
// each tile gets the lights it must list and the ones it may list.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "systems/shadows/gpu_light.h"

namespace sg::test {

struct TileLightSets {
  std::vector<uint32_t> must;  // reach the tile with its bound shrunk by a hair
  std::vector<uint32_t> may;   // reach it with its bound grown by a hair
};

// `depth` is the scene's depth buffer (row-major, 1 = background) rendered with
// `view_projection`; tiles are row-major.
std::vector<TileLightSets> reference_light_tiles(std::span<const float> depth, uint32_t width,
                                                 uint32_t height, const glm::mat4& view_projection,
                                                 std::span<const shadows::GpuLight> lights);

}  // namespace sg::test
