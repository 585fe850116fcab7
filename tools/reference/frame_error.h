// SPDX-License-Identifier: MIT
#pragma once
// How far a whole frame's shadows are from ray-traced visibility, every light at once: the
// (pixel, light) pairs the frame shaded (systems/lighting/shadow_probe.h), each with the
// engine's shade and the references' visibility there. A pixel's error is its lights' errors
// weighted by each light's shadow weight there (what its shadow can move the pixel), so a pixel
// counts once however many lights reach it, and a light that adds little to it counts little.
#include <cstdint>
#include <vector>

namespace sg::reference {

struct TracedPair {
  uint32_t pixel = 0;  // y * width + x
  uint32_t light = 0;  // the frame's light record
  float shade = 0.0f;  // the engine's: 0 lit .. 1 shadowed
  float weight = 0.0f;
  float hard = 0.0f;       // hard reference visibility, 0 or 1
  float reference = 0.0f;  // visibility the shade is measured against: soft for PCSS, else hard
};

struct LightError {
  uint32_t light = 0;
  uint64_t pairs = 0;                // its pairs outside its edge band
  double weight_share = 0.0;         // of all pairs' weight outside the bands
  double misclassified = 0.0;        // its pairs' weighted fraction on the wrong side of 0.5
  double mae = 0.0;                  // its pairs' weighted mean |engine visibility - reference|
  double frame_misclassified = 0.0;  // what it adds to FrameError::misclassified
  double frame_mae = 0.0;            // what it adds to FrameError::mae
};

struct FrameError {
  uint64_t lit_pixels = 0;  // pixels with a pair outside its light's edge band
  uint64_t pairs = 0;       // pairs compared
  uint64_t band_pairs = 0;  // pairs left out, in their light's edge band
  // Means over lit pixels of each pixel's weighted fraction of lights misclassified against the
  // hard reference, and of its weighted mean absolute visibility error against the reference.
  double misclassified = 0.0;
  double mae = 0.0;
  std::vector<LightError>
      lights;  // every light with pairs, the worst first (frame_misclassified, then frame_mae)
};

// `pairs` of a width x height frame, in any order (sorted here). A pair lies in its light's edge
// band where a pixel within `band_radius` pixels (Chebyshev distance) has a pair of the same light
// on the other side of the hard reference: there rasterization makes either answer right.
FrameError frame_error(std::vector<TracedPair> pairs, uint32_t width, uint32_t height, int band_radius);

}  // namespace sg::reference
