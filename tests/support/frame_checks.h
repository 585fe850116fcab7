// SPDX-License-Identifier: MIT
#pragma once
// What tests of whole frames compare: the passes a plan ran, and how far two pictures are apart.
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "rendergraph/core/compiled_plan.h"
#include "rendergraph/device/readback.h"

namespace sg::test {

inline std::vector<std::string> executed_passes(const rg::CompiledPlan& plan) {
  std::vector<std::string> names;
  for (const rg::CompiledPass& pass : plan.passes) names.push_back(pass.name);
  return names;
}

// The largest difference of any channel of any pixel, in levels of 255.
inline int largest_difference(const vk::Rgba8Image& a, const vk::Rgba8Image& b) {
  int largest = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    largest = std::max(largest, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
  return largest;
}

// The share of pixels whose worst color channel differs by more than `levels` of 255.
inline double share_differing(const vk::Rgba8Image& a, const vk::Rgba8Image& b, int levels) {
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) {
    int largest = 0;
    for (size_t c = 0; c < 3; ++c)
      largest = std::max(largest, std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])));
    differing += largest > levels;
  }
  return double(differing) / double(a.pixels.size() / 4);
}

}  // namespace sg::test
