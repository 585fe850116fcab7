// SPDX-License-Identifier: MIT
#pragma once
// Staged uploads into device-local buffers: every copy added to a batch goes through one
// host-visible staging buffer and one submission, so loading a scene costs one round trip.
#include <cstddef>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::vk {

class Buffer;
class Image;
class VulkanContext;

class UploadBatch {
 public:
  explicit UploadBatch(VulkanContext& context) : context_(context) {}

  // Queues `bytes` for `dst` at `dst_offset`; the data is copied now, so `bytes` may die.
  void copy_bytes(const Buffer& dst, std::span<const std::byte> bytes, VkDeviceSize dst_offset = 0);
  template <class T, size_t N>
  void copy(const Buffer& dst, std::span<const T, N> items, VkDeviceSize dst_offset = 0) {
    copy_bytes(dst, std::as_bytes(items), dst_offset);
  }

  // Queues tightly packed 4-byte texels for mip 0 of every layer of `dst`, layer after layer
  // (bytes = width * height * 4 * layers). After submit() the whole image is in
  // READ_ONLY_OPTIMAL, ready to sample.
  void copy_to_image(const Image& dst, uint32_t layers, std::span<const std::byte> texels);

  // Submits every queued copy and waits. Afterwards the data is visible to any later command
  // on the queue, at any stage.
  void submit();

 private:
  struct Pending {
    VkBuffer dst;
    VkDeviceSize dst_offset;
    size_t staging_offset;
    size_t size;
  };
  struct PendingImage {
    VkImage dst;
    VkImageAspectFlags aspect;
    VkExtent2D extent;
    uint32_t layers;
    size_t staging_offset;
  };
  size_t stage(std::span<const std::byte> bytes);

  VulkanContext& context_;
  std::vector<std::byte> staged_;
  std::vector<Pending> pending_;
  std::vector<PendingImage> pending_images_;
};

}  // namespace sg::vk
