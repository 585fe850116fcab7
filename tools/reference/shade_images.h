// SPDX-License-Identifier: MIT
#pragma once
// Pictures of the reference and the render, for a person to see where they differ.
#include <cstdint>
#include <vector>

#include "rendergraph/device/readback.h"

namespace sg::reference {

// Visibility as grey (white lit, black shadowed); pixels not measured dark blue.
vk::Rgba8Image visibility_image(uint32_t width, uint32_t height, const std::vector<float>& visibility,
                                const std::vector<bool>& measured);

// engine - reference per pixel: red where the render is darker, cyan where it is lighter, black
// where they agree; pixels not measured dark blue.
vk::Rgba8Image difference_image(uint32_t width, uint32_t height, const std::vector<float>& engine,
                                const std::vector<float>& reference, const std::vector<bool>& measured);

}  // namespace sg::reference
