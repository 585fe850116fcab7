// SPDX-License-Identifier: MIT
#include "tools/reference/frame_error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sg::reference {
namespace {

bool shadowed(float visibility) { return visibility < 0.5f; }

// In-band flags for one light's pairs [first, end), sorted by pixel; `classes` is a frame-sized
// scratch image of -1 that is left as it was found.
void mark_band(const std::vector<TracedPair>& pairs, size_t first, size_t end, uint32_t width,
               uint32_t height, int radius, std::vector<int8_t>& classes, std::vector<uint8_t>& in_band) {
  for (size_t i = first; i < end; ++i) classes[pairs[i].pixel] = shadowed(pairs[i].hard) ? 1 : 0;
  for (size_t i = first; i < end; ++i) {
    const int x = int(pairs[i].pixel % width);
    const int y = int(pairs[i].pixel / width);
    const int8_t own = classes[pairs[i].pixel];
    bool band = false;
    for (int dy = -radius; dy <= radius && !band; ++dy) {
      const int ny = y + dy;
      if (ny < 0 || ny >= int(height)) continue;
      for (int dx = -radius; dx <= radius; ++dx) {
        const int nx = x + dx;
        if (nx < 0 || nx >= int(width)) continue;
        const int8_t other = classes[size_t(ny) * width + size_t(nx)];
        if (other >= 0 && other != own) {
          band = true;
          break;
        }
      }
    }
    in_band[i] = band ? 1 : 0;
  }
  for (size_t i = first; i < end; ++i) classes[pairs[i].pixel] = -1;
}

struct PixelSums {
  double weight = 0.0;
  double misclassified = 0.0;  // weight of its misclassified lights
  double error = 0.0;          // weight times absolute error
};

}  // namespace

FrameError frame_error(std::vector<TracedPair> pairs, uint32_t width, uint32_t height, int band_radius) {
  // Weights too small for half precision arrive as 0: those lights cannot change the pixel.
  std::erase_if(pairs, [](const TracedPair& pair) { return !(pair.weight > 0.0f); });
  std::sort(pairs.begin(), pairs.end(), [](const TracedPair& a, const TracedPair& b) {
    return a.light != b.light ? a.light < b.light : a.pixel < b.pixel;
  });
  std::vector<uint8_t> in_band(pairs.size(), 0);
  std::vector<int8_t> classes(size_t(width) * height, -1);
  for (size_t first = 0; first < pairs.size();) {
    size_t end = first;
    while (end < pairs.size() && pairs[end].light == pairs[first].light) ++end;
    mark_band(pairs, first, end, width, height, band_radius, classes, in_band);
    first = end;
  }

  FrameError out;
  std::vector<PixelSums> pixels(size_t(width) * height);
  double total_weight = 0.0;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const TracedPair& pair = pairs[i];
    if (in_band[i]) {
      ++out.band_pairs;
      continue;
    }
    const float engine = 1.0f - pair.shade;
    PixelSums& sums = pixels[pair.pixel];
    sums.weight += pair.weight;
    sums.misclassified += shadowed(engine) != shadowed(pair.hard) ? pair.weight : 0.0;
    sums.error += pair.weight * std::abs(engine - pair.reference);
    total_weight += pair.weight;
    ++out.pairs;
  }
  for (const PixelSums& sums : pixels) {
    if (sums.weight <= 0.0) continue;
    ++out.lit_pixels;
    out.misclassified += sums.misclassified / sums.weight;
    out.mae += sums.error / sums.weight;
  }
  if (out.lit_pixels == 0) return out;
  const double per_pixel = 1.0 / double(out.lit_pixels);
  out.misclassified *= per_pixel;
  out.mae *= per_pixel;

  for (size_t i = 0; i < pairs.size(); ++i) {
    if (in_band[i]) continue;
    const TracedPair& pair = pairs[i];
    if (out.lights.empty() || out.lights.back().light != pair.light) out.lights.push_back({pair.light});
    LightError& light = out.lights.back();
    const float engine = 1.0f - pair.shade;
    const double wrong = shadowed(engine) != shadowed(pair.hard) ? pair.weight : 0.0;
    const double error = pair.weight * std::abs(engine - pair.reference);
    const double pixel_weight = pixels[pair.pixel].weight;
    ++light.pairs;
    light.weight_share += pair.weight;
    light.misclassified += wrong;
    light.mae += error;
    light.frame_misclassified += wrong / pixel_weight * per_pixel;
    light.frame_mae += error / pixel_weight * per_pixel;
  }
  for (LightError& light : out.lights) {
    if (light.weight_share > 0.0) {
      light.misclassified /= light.weight_share;
      light.mae /= light.weight_share;
    }
    light.weight_share /= total_weight;
  }
  std::sort(out.lights.begin(), out.lights.end(), [](const LightError& a, const LightError& b) {
    return a.frame_misclassified != b.frame_misclassified ? a.frame_misclassified > b.frame_misclassified
                                                          : a.frame_mae > b.frame_mae;
  });
  return out;
}

}  // namespace sg::reference
