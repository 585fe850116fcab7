#include "rendergraph/vulkan/upload.h"

#include <cstring>

#include "rendergraph/vulkan/barriers.h"
#include "rendergraph/vulkan/context.h"
#include "rendergraph/vulkan/resources.h"
#include "rendergraph/vulkan/vulkan_error.h"

namespace sg::vk {

void UploadBatch::copy_bytes(const Buffer& dst, std::span<const std::byte> bytes, VkDeviceSize dst_offset) {
  if (bytes.empty()) return;
  if (dst_offset + bytes.size() > dst.size()) {
    throw VulkanError("upload of " + std::to_string(bytes.size()) + " bytes at offset " +
                      std::to_string(dst_offset) + " overruns a buffer of " +
                      std::to_string(dst.size()) + " bytes");
  }
  // Keep every source 16-byte aligned in the staging buffer (vkCmdCopyBuffer needs 4).
  const size_t offset = (staged_.size() + 15) & ~size_t{15};
  staged_.resize(offset + bytes.size());
  std::memcpy(staged_.data() + offset, bytes.data(), bytes.size());
  pending_.push_back({dst.handle(), dst_offset, offset, bytes.size()});
}

void UploadBatch::submit() {
  if (pending_.empty()) return;
  Buffer staging(context_, {staged_.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::upload,
                            "upload staging"});
  std::memcpy(staging.mapped(), staged_.data(), staged_.size());
  context_.submit_and_wait([&](VkCommandBuffer cmd) {
    for (const Pending& p : pending_) {
      const VkBufferCopy region{p.staging_offset, p.dst_offset, p.size};
      vkCmdCopyBuffer(cmd, staging.handle(), p.dst, 1, &region);
    }
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
  });
  staged_.clear();
  pending_.clear();
}

}  // namespace sg::vk
