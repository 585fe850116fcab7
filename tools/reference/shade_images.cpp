// SPDX-License-Identifier: MIT
#include "tools/reference/shade_images.h"

#include <algorithm>
#include <cmath>

namespace sg::reference {
namespace {

constexpr uint8_t not_measured[4] = {0, 0, 64, 255};

uint8_t byte(float value) { return uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); }

template <typename Color>
vk::Rgba8Image image(uint32_t width, uint32_t height, const std::vector<bool>& measured, Color color) {
  vk::Rgba8Image out{width, height, std::vector<uint8_t>(size_t{width} * height * 4)};
  for (size_t i = 0; i < measured.size(); ++i) {
    uint8_t* pixel = &out.pixels[i * 4];
    if (!measured[i]) {
      std::copy(std::begin(not_measured), std::end(not_measured), pixel);
      continue;
    }
    color(i, pixel);
    pixel[3] = 255;
  }
  return out;
}

}  // namespace

vk::Rgba8Image visibility_image(uint32_t width, uint32_t height, const std::vector<float>& visibility,
                                const std::vector<bool>& measured) {
  return image(width, height, measured,
               [&](size_t i, uint8_t* pixel) { pixel[0] = pixel[1] = pixel[2] = byte(visibility[i]); });
}

vk::Rgba8Image difference_image(uint32_t width, uint32_t height, const std::vector<float>& engine,
                                const std::vector<float>& reference, const std::vector<bool>& measured) {
  return image(width, height, measured, [&](size_t i, uint8_t* pixel) {
    const float difference = engine[i] - reference[i];
    pixel[0] = byte(-difference);
    pixel[1] = pixel[2] = byte(difference);
  });
}

}  // namespace sg::reference
