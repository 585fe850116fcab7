// SPDX-License-Identifier: MIT
#pragma once
// Copies a color image back to the CPU (screenshots, tests).
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::vk {

class Image;
class VulkanContext;

// Tightly packed 8-bit RGBA, rows top to bottom.
struct Rgba8Image {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> pixels;

  const uint8_t* at(uint32_t x, uint32_t y) const { return &pixels[(size_t{y} * width + x) * 4]; }
};

// The linear value of one 8-bit sRGB-encoded channel (IEC 61966-2-1), as read_rgba8 returns the
// channels of an SRGB image: for measuring light in a rendered picture.
float srgb_to_linear(uint8_t encoded);

// Reads mip 0, layer 0 of an 8-bit RGBA or BGRA image (UNORM or SRGB: the stored bytes are
// returned as they are). The image must be in TRANSFER_SRC_OPTIMAL with its writes made
// available to transfer reads by an earlier barrier on the same queue. Waits for the copy.
Rgba8Image read_rgba8(VulkanContext& context, const Image& image);

// One layer of a D32_SFLOAT image, rows top to bottom.
struct DepthImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> depths;
  float at(uint32_t x, uint32_t y) const { return depths[size_t{y} * width + x]; }
};

// Reads mip 0 of `layer` of a D32_SFLOAT image that is in `layout` with its writes available to
// transfers or to the fragment shader (a shadow map after the frame), and leaves it in
// `layout`. Waits for the copy.
DepthImage read_depth_layer(VulkanContext& context, const Image& image, uint32_t layer, VkImageLayout layout);

}  // namespace sg::vk
