// SPDX-License-Identifier: MIT
#pragma once
// One host-visible buffer per frame in flight, for data the CPU rewrites every frame (instance
// transforms, indirect draws, light records), in stream memory (MemoryUsage): where the device
// maps device-local memory, the GPU's passes read it from there. Or for data the GPU writes for
// the CPU to read a few frames later (feedback), in readback memory. The CPU writes slot s while
// the GPU may still read the other slots, so no frame waits for another.
//
// Contract: write slot s only after FrameRing::begin_frame returned slot s (the GPU has finished
// with it); that also makes growing (recreating) the buffer safe.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/resources.h"

namespace sg::vk {

class FrameBuffers {
 public:
  // `texel_format`: each slot's buffer also has a texel view in that format (Buffer::texel_view).
  // `memory`: stream or readback.
  FrameBuffers(VulkanContext& context, VkBufferUsageFlags usage, uint32_t frames_in_flight, std::string name,
               VkFormat texel_format = VK_FORMAT_UNDEFINED, MemoryUsage memory = MemoryUsage::stream);

  // Copies `items` to the start of the slot's buffer, growing it when needed. An empty span
  // leaves a small buffer, so descriptors always have something valid to point at.
  template <class T>
  const Buffer& write(uint32_t slot, std::span<const T> items) {
    const Buffer& buffer = reserve(slot, items.size_bytes());
    if (!items.empty()) std::memcpy(buffer.mapped(), items.data(), items.size_bytes());
    return buffer;
  }

  const Buffer& buffer(uint32_t slot) const { return buffers_[slot]; }

  // The slot's buffer, grown to at least `bytes` (never empty); what it holds is undefined until
  // written through mapped(). For callers that fill it themselves, say from several threads.
  const Buffer& reserve(uint32_t slot, VkDeviceSize bytes);

 private:
  VulkanContext& context_;
  VkBufferUsageFlags usage_;
  VkFormat texel_format_;
  MemoryUsage memory_;
  std::string name_;
  std::vector<Buffer> buffers_;
};

}  // namespace sg::vk
