#pragma once
// Staged uploads into device-local buffers: every copy added to a batch goes through one
// host-visible staging buffer and one submission, so loading a scene costs one round trip.
#include <cstddef>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::vk {

class Buffer;
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
  VulkanContext& context_;
  std::vector<std::byte> staged_;
  std::vector<Pending> pending_;
};

}  // namespace sg::vk
