// SPDX-License-Identifier: MIT
#pragma once
// How far an engine's shadow is from the ray-traced reference, per light. Images are row-major
// `width` x `height` values; `measured` says which pixels count (a surface point the light
// reaches); visibilities are 1 lit .. 0 shadowed, the engine's as measured from its frames.
#include <cstdint>
#include <vector>

namespace sg::reference {

struct ShadowImages {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<bool> measured;
  std::vector<float> hard;    // hard_visibility: 0 or 1
  std::vector<float> soft;    // soft_visibility: the fraction of the emitter seen
  std::vector<float> engine;  // the render's visibility
};

// Pixels of the hard reference within `radius` pixels (Chebyshev distance) of a measured pixel
// of the other class: where rasterization makes any answer right.
std::vector<bool> edge_band(const ShadowImages& images, int radius);

struct ErrorStats {
  uint64_t pixels = 0;
  double mean_absolute = 0.0;
  double rms = 0.0;
};

struct ShadowMetrics {
  uint64_t measured = 0;      // pixels compared
  uint64_t shadowed = 0;      // of them, shadowed in the hard reference
  uint64_t outside_band = 0;  // measured pixels outside the edge band
  // Outside the band: the engine's visibility on the other side of 0.5 from the hard reference.
  double misclassified = 0.0;  // fraction of outside_band
  // Against the soft reference: inside its penumbra (partly visible emitter) and outside it.
  ErrorStats penumbra;
  ErrorStats umbra_and_lit;
  // Fully lit in both references and outside the band: `lit` pixels; of them, darkened by more
  // than 0.1 in the render: self-shadowing (acne), as a fraction of `lit`.
  uint64_t lit = 0;
  double acne = 0.0;
};

// `band_radius`: the edge band's half width in pixels (2 in issue 15).
ShadowMetrics shadow_metrics(const ShadowImages& images, int band_radius);

}  // namespace sg::reference
