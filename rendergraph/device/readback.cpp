// SPDX-License-Identifier: MIT
#include "rendergraph/device/readback.h"

#include <cmath>
#include <cstring>
#include <span>
#include <utility>

#include "rendergraph/device/barriers.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

float srgb_to_linear(uint8_t encoded) {
  const float c = float(encoded) / 255.0f;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

namespace {

bool is_bgra(VkFormat format) {
  return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB;
}
bool is_rgba(VkFormat format) {
  return format == VK_FORMAT_R8G8B8A8_UNORM || format == VK_FORMAT_R8G8B8A8_SRGB;
}

// Copies mip 0 of `layer` into `out` (as many bytes as the layer has) and waits. An image not
// in TRANSFER_SRC_OPTIMAL is moved there for the copy and back to `layout` after it.
void copy_layer_to_host(VulkanContext& context, const Image& image, uint32_t layer, VkImageLayout layout,
                        std::span<std::byte> out) {
  const VkExtent2D extent = image.extent();
  Buffer staging(context,
                 {out.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::readback, "readback staging"});
  const bool move = layout != VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  context.submit_and_wait([&](VkCommandBuffer cmd) {
    if (move) {
      transition(cmd, {image.handle(), image.aspect(), layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, layer, 1});
    }
    VkBufferImageCopy region{};
    region.imageSubresource = {image.aspect(), 0, layer, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1,
                           &region);
    if (move) {
      transition(cmd, {image.handle(), image.aspect(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                       VK_ACCESS_2_NONE, layer, 1});
    }
    // Make the copy visible to the host read below.
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  });
  std::memcpy(out.data(), staging.mapped(), out.size());
}

}  // namespace

Rgba8Image read_rgba8(VulkanContext& context, const Image& image) {
  if (!is_rgba(image.format()) && !is_bgra(image.format())) {
    throw VulkanError("read_rgba8 supports 8-bit RGBA/BGRA images only (format " +
                      std::to_string(image.format()) + ")");
  }
  const VkExtent2D extent = image.extent();
  Rgba8Image out{extent.width, extent.height, std::vector<uint8_t>(size_t{extent.width} * extent.height * 4)};
  copy_layer_to_host(context, image, 0, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     std::as_writable_bytes(std::span(out.pixels)));
  if (is_bgra(image.format())) {
    for (size_t i = 0; i < out.pixels.size(); i += 4) std::swap(out.pixels[i], out.pixels[i + 2]);
  }
  return out;
}

DepthImage read_depth_layer(VulkanContext& context, const Image& image, uint32_t layer,
                            VkImageLayout layout) {
  if (image.format() != VK_FORMAT_D32_SFLOAT) {
    throw VulkanError("read_depth_layer supports D32_SFLOAT images only (format " +
                      std::to_string(image.format()) + ")");
  }
  const VkExtent2D extent = image.extent();
  DepthImage out{extent.width, extent.height, std::vector<float>(size_t{extent.width} * extent.height)};
  copy_layer_to_host(context, image, layer, layout, std::as_writable_bytes(std::span(out.depths)));
  return out;
}

}  // namespace sg::vk
