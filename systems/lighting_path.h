#pragma once
#include <cstdint>
#include <string_view>

namespace sg {

// How the frame is lit. Both tiled paths cull lights per 16x16 screen tile and shade a pixel
// only with its tile's lights, each with its own algorithm:
// - forward: depth prepass, light culling, one forward pass;
// - deferred: G-buffer, light culling, a compute pass per light group (each holding one
//   algorithm's code);
// - every_light: one forward pass with every light at every pixel (the --naive baseline);
// - automatic: whichever measured faster on the device's kind (SceneRenderer says which).
enum class LightingPath { automatic, forward, deferred, every_light };

// What the lighting writes: the lit picture, or the shadow-only debug view (white diffuse surfaces
// under white lights of the same intensities, shadows at full density, no ambient).
enum class LightingView : uint32_t { lit = 0, shadows = 1 };

constexpr std::string_view lighting_path_name(LightingPath path) {
  switch (path) {
    case LightingPath::automatic: return "auto";
    case LightingPath::forward: return "forward";
    case LightingPath::deferred: return "deferred";
    case LightingPath::every_light: return "every light";
  }
  return "unknown";
}

}  // namespace sg
