// SPDX-License-Identifier: MIT
#pragma once
// Buffers and images that own their Vulkan handle and their slice of suballocated memory.
// Move-only; destroyed with their owner, which must not outlive the VulkanContext.
#include <cstdint>
#include <memory>
#include <string>

#include <vulkan/vulkan.h>

#include "rendergraph/device/gpu_allocator.h"
#include "rendergraph/device/image_views.h"

namespace sg::vk {

class VulkanContext;

struct BufferDesc {
  VkDeviceSize size = 0;
  VkBufferUsageFlags usage = 0;
  MemoryUsage memory = MemoryUsage::gpu_only;
  std::string name;  // debug name, shown by validation messages and capture tools
  // Not VK_FORMAT_UNDEFINED: a view of the whole buffer as texels of this format (texel_view),
  // for a texel-buffer usage.
  VkFormat texel_format = VK_FORMAT_UNDEFINED;
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(VulkanContext& context, const BufferDesc& desc);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;

  VkBuffer handle() const { return buffer_; }
  // VK_NULL_HANDLE unless the buffer was made with a texel_format.
  VkBufferView texel_view() const { return texel_view_; }
  VkDeviceSize size() const { return size_; }
  // Host address of the buffer's first byte; null for gpu_only memory.
  void* mapped() const { return allocation_.mapped; }

 private:
  void reset();

  VulkanContext* context_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkBufferView texel_view_ = VK_NULL_HANDLE;
  Allocation allocation_;
  VkDeviceSize size_ = 0;
};

struct ImageDesc {
  VkExtent2D extent{};
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImageUsageFlags usage = 0;
  uint32_t mip_levels = 1;
  uint32_t array_layers = 1;
  VkImageViewType view_type = VK_IMAGE_VIEW_TYPE_2D;  // of the view over all subresources
  std::string name;
};

class Image {
 public:
  Image() = default;
  Image(VulkanContext& context, const ImageDesc& desc);
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }  // all mips and layers
  // Views of parts of the image (one layer, one cube, one mip), kept until the image dies.
  ImageViewCache& views() const { return *views_; }
  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  uint32_t mip_levels() const { return mip_levels_; }
  uint32_t array_layers() const { return array_layers_; }
  bool cube_compatible() const { return cube_compatible_; }
  VkImageAspectFlags aspect() const;
  // A number no other image of the process had: tells a recreated image from its predecessor
  // even when the driver hands out the same handle again. 0 for an empty Image.
  uint64_t serial() const { return serial_; }

 private:
  void reset();

  VulkanContext* context_ = nullptr;
  VkImage image_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  std::unique_ptr<ImageViewCache> views_;
  Allocation allocation_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  uint32_t mip_levels_ = 0;
  uint32_t array_layers_ = 0;
  bool cube_compatible_ = false;
  uint64_t serial_ = 0;
};

}  // namespace sg::vk
