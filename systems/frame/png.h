// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "rendergraph/device/readback.h"

namespace sg {

// Writes `image` as an 8-bit RGBA PNG. Throws std::runtime_error naming the path on failure.
void write_png(const std::string& path, const vk::Rgba8Image& image);

}  // namespace sg
