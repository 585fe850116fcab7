// SPDX-License-Identifier: MIT
#include "rendergraph/device/frame_buffers.h"

#include <algorithm>

namespace sg::vk {
namespace {

constexpr VkDeviceSize minimum_size = 256;

}  // namespace

FrameBuffers::FrameBuffers(VulkanContext& context, VkBufferUsageFlags usage, uint32_t frames_in_flight,
                           std::string name, VkFormat texel_format, MemoryUsage memory)
    : context_(context),
      usage_(usage),
      texel_format_(texel_format),
      memory_(memory),
      name_(std::move(name)),
      buffers_(frames_in_flight) {
  for (uint32_t slot = 0; slot < frames_in_flight; ++slot) reserve(slot, minimum_size);
}

const Buffer& FrameBuffers::reserve(uint32_t slot, VkDeviceSize bytes) {
  Buffer& buffer = buffers_[slot];
  if (buffer.size() < bytes || buffer.handle() == VK_NULL_HANDLE) {
    // Grow by half again so that a slowly growing scene does not recreate every frame.
    const VkDeviceSize size = std::max({minimum_size, bytes, buffer.size() + buffer.size() / 2});
    buffer = Buffer(context_,
                    {size, usage_, memory_, name_ + " (slot " + std::to_string(slot) + ")", texel_format_});
  }
  return buffer;
}

}  // namespace sg::vk
