// SPDX-License-Identifier: MIT
#include "tools/reference/metrics.h"

#include <algorithm>
#include <cmath>

namespace sg::reference {
namespace {

// The soft reference's fraction counts as partial (penumbra) between these.
constexpr float fully_shadowed = 1e-4f;
constexpr float fully_lit = 1.0f - 1e-4f;
// A lit pixel darker than this in the render is acne.
constexpr float acne_darkening = 0.1f;

struct ErrorSum {
  uint64_t pixels = 0;
  double absolute = 0.0;
  double squared = 0.0;

  void add(double error) {
    ++pixels;
    absolute += std::abs(error);
    squared += error * error;
  }
  ErrorStats stats() const {
    if (pixels == 0) return {};
    return {pixels, absolute / double(pixels), std::sqrt(squared / double(pixels))};
  }
};

}  // namespace

std::vector<bool> edge_band(const ShadowImages& images, int radius) {
  const int w = int(images.width);
  const int h = int(images.height);
  std::vector<bool> band(images.measured.size(), false);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      if (!images.measured[i]) continue;
      for (int dy = -radius; dy <= radius && !band[i]; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
          const int nx = x + dx;
          const int ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const size_t n = size_t(ny) * w + nx;
          if (images.measured[n] && images.hard[n] != images.hard[i]) {
            band[i] = true;
            break;
          }
        }
      }
    }
  }
  return band;
}

ShadowMetrics shadow_metrics(const ShadowImages& images, int band_radius) {
  const std::vector<bool> band = edge_band(images, band_radius);
  ShadowMetrics m;
  uint64_t misclassified = 0;
  uint64_t darkened = 0;
  ErrorSum penumbra, elsewhere;
  for (size_t i = 0; i < images.measured.size(); ++i) {
    if (!images.measured[i]) continue;
    ++m.measured;
    const bool shadowed = images.hard[i] < 0.5f;
    m.shadowed += shadowed;
    const float soft = images.soft[i];
    const float engine = images.engine[i];
    (soft > fully_shadowed && soft < fully_lit ? penumbra : elsewhere).add(engine - soft);
    if (band[i]) continue;
    ++m.outside_band;
    misclassified += (engine < 0.5f) != shadowed;
    if (!shadowed && soft >= fully_lit) {
      ++m.lit;
      darkened += engine < 1.0f - acne_darkening;
    }
  }
  m.misclassified = m.outside_band ? double(misclassified) / double(m.outside_band) : 0.0;
  m.acne = m.lit ? double(darkened) / double(m.lit) : 0.0;
  m.penumbra = penumbra.stats();
  m.umbra_and_lit = elsewhere.stats();
  return m;
}

}  // namespace sg::reference
