#include "rendergraph/vulkan/readback.h"

#include <cstring>
#include <utility>

#include "rendergraph/vulkan/barriers.h"
#include "rendergraph/vulkan/context.h"
#include "rendergraph/vulkan/resources.h"
#include "rendergraph/vulkan/vulkan_error.h"

namespace sg::vk {
namespace {

bool is_bgra(VkFormat format) {
  return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB;
}
bool is_rgba(VkFormat format) {
  return format == VK_FORMAT_R8G8B8A8_UNORM || format == VK_FORMAT_R8G8B8A8_SRGB;
}

}  // namespace

Rgba8Image read_rgba8(VulkanContext& context, const Image& image) {
  if (!is_rgba(image.format()) && !is_bgra(image.format())) {
    throw VulkanError("read_rgba8 supports 8-bit RGBA/BGRA images only (format " +
                      std::to_string(image.format()) + ")");
  }
  const VkExtent2D extent = image.extent();
  const VkDeviceSize size = VkDeviceSize{extent.width} * extent.height * 4;
  Buffer staging(context, {size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::readback,
                           "readback staging"});
  context.submit_and_wait([&](VkCommandBuffer cmd) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           staging.handle(), 1, &region);
    // Make the copy visible to the host read below.
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  });

  Rgba8Image out{extent.width, extent.height, std::vector<uint8_t>(size)};
  std::memcpy(out.pixels.data(), staging.mapped(), size);
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
  const VkDeviceSize size = VkDeviceSize{extent.width} * extent.height * sizeof(float);
  Buffer staging(context, {size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::readback,
                           "depth readback staging"});
  context.submit_and_wait([&](VkCommandBuffer cmd) {
    transition(cmd, {image.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, layout,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                     VK_ACCESS_2_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                     VK_ACCESS_2_TRANSFER_READ_BIT, layer, 1});

    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, layer, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           staging.handle(), 1, &region);

    // Back to where the image was, for the frames that follow.
    transition(cmd, {image.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     layout, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                     VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_NONE, layer, 1});
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  });

  DepthImage out{extent.width, extent.height, std::vector<float>(size_t{extent.width} * extent.height)};
  std::memcpy(out.depths.data(), staging.mapped(), size);
  return out;
}

}  // namespace sg::vk
