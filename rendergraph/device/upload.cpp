// SPDX-License-Identifier: MIT
#include "rendergraph/device/upload.h"

#include <cstring>

#include "rendergraph/device/barriers.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

void UploadBatch::copy_bytes(const Buffer& dst, std::span<const std::byte> bytes, VkDeviceSize dst_offset) {
  if (bytes.empty()) return;
  if (dst_offset + bytes.size() > dst.size()) {
    throw VulkanError("upload of " + std::to_string(bytes.size()) + " bytes at offset " +
                      std::to_string(dst_offset) + " overruns a buffer of " + std::to_string(dst.size()) +
                      " bytes");
  }
  pending_.push_back({dst.handle(), dst_offset, stage(bytes), bytes.size()});
}

void UploadBatch::copy_to_image(const Image& dst, uint32_t layers, std::span<const std::byte> texels) {
  const VkExtent2D extent = dst.extent();
  if (texels.size() != size_t{extent.width} * extent.height * 4 * layers) {
    throw VulkanError("image upload of " + std::to_string(texels.size()) + " bytes does not fill " +
                      std::to_string(layers) + " layers of " + std::to_string(extent.width) + "x" +
                      std::to_string(extent.height) + " 4-byte texels");
  }
  pending_images_.push_back({dst.handle(), dst.aspect(), extent, layers, stage(texels)});
}

size_t UploadBatch::stage(std::span<const std::byte> bytes) {
  // Keep every source 16-byte aligned in the staging buffer (copies need 4, texel copies the
  // texel size).
  const size_t offset = (staged_.size() + 15) & ~size_t{15};
  staged_.resize(offset + bytes.size());
  std::memcpy(staged_.data() + offset, bytes.data(), bytes.size());
  return offset;
}

void UploadBatch::submit() {
  if (pending_.empty() && pending_images_.empty()) return;
  Buffer staging(context_,
                 {staged_.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::upload, "upload staging"});
  std::memcpy(staging.mapped(), staged_.data(), staged_.size());
  context_.submit_and_wait([&](VkCommandBuffer cmd) {
    for (const Pending& p : pending_) {
      const VkBufferCopy region{p.staging_offset, p.dst_offset, p.size};
      vkCmdCopyBuffer(cmd, staging.handle(), p.dst, 1, &region);
    }
    for (const PendingImage& p : pending_images_) {
      transition(cmd, {p.dst, p.aspect, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_TRANSFER_WRITE_BIT});
      VkBufferImageCopy region{};
      region.bufferOffset = p.staging_offset;
      region.imageSubresource = {p.aspect, 0, 0, p.layers};
      region.imageExtent = {p.extent.width, p.extent.height, 1};
      vkCmdCopyBufferToImage(cmd, staging.handle(), p.dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      transition(cmd,
                 {p.dst, p.aspect, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                  VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT});
    }
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
  });
  staged_.clear();
  pending_.clear();
  pending_images_.clear();
}

}  // namespace sg::vk
