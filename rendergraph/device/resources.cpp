// SPDX-License-Identifier: MIT
#include "rendergraph/device/resources.h"

#include <atomic>
#include <utility>

#include "rendergraph/device/context.h"
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

Buffer::Buffer(VulkanContext& context, const BufferDesc& desc) : context_(&context), size_(desc.size) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = desc.size;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(context.device(), &info, nullptr, &buffer_), "vkCreateBuffer " + desc.name);
  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(context.device(), buffer_, &requirements);
  try {
    allocation_ = context.allocator().allocate(requirements, desc.memory, ResourceTiling::linear);
  } catch (...) {
    vkDestroyBuffer(context.device(), buffer_, nullptr);
    throw;
  }
  check(vkBindBufferMemory(context.device(), buffer_, allocation_.memory, allocation_.offset),
        "vkBindBufferMemory " + desc.name);
  if (!desc.name.empty()) {
    context.set_name(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(buffer_), desc.name.c_str());
  }
  if (desc.texel_format != VK_FORMAT_UNDEFINED) {
    VkBufferViewCreateInfo view{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    view.buffer = buffer_;
    view.format = desc.texel_format;
    view.range = VK_WHOLE_SIZE;
    const VkResult result = vkCreateBufferView(context.device(), &view, nullptr, &texel_view_);
    if (result != VK_SUCCESS) {
      texel_view_ = VK_NULL_HANDLE;
      reset();
    }
    check(result, "vkCreateBufferView " + desc.name);
  }
}

Buffer::~Buffer() { reset(); }

Buffer::Buffer(Buffer&& other) noexcept
    : context_(std::exchange(other.context_, nullptr)),
      buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)),
      texel_view_(std::exchange(other.texel_view_, VK_NULL_HANDLE)),
      allocation_(std::exchange(other.allocation_, {})),
      size_(std::exchange(other.size_, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    reset();
    context_ = std::exchange(other.context_, nullptr);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    texel_view_ = std::exchange(other.texel_view_, VK_NULL_HANDLE);
    allocation_ = std::exchange(other.allocation_, {});
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

void Buffer::reset() {
  if (buffer_ == VK_NULL_HANDLE) return;
  if (texel_view_ != VK_NULL_HANDLE) vkDestroyBufferView(context_->device(), texel_view_, nullptr);
  texel_view_ = VK_NULL_HANDLE;
  vkDestroyBuffer(context_->device(), buffer_, nullptr);
  context_->allocator().free(allocation_);
  buffer_ = VK_NULL_HANDLE;
}

Image::Image(VulkanContext& context, const ImageDesc& desc)
    : context_(&context),
      format_(desc.format),
      extent_(desc.extent),
      mip_levels_(desc.mip_levels),
      array_layers_(desc.array_layers),
      cube_compatible_(desc.view_type == VK_IMAGE_VIEW_TYPE_CUBE ||
                       desc.view_type == VK_IMAGE_VIEW_TYPE_CUBE_ARRAY) {
  static std::atomic<uint64_t> images_created{0};
  serial_ = ++images_created;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  if (cube_compatible_) info.flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.extent.width, desc.extent.height, 1};
  info.mipLevels = desc.mip_levels;
  info.arrayLayers = desc.array_layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(vkCreateImage(context.device(), &info, nullptr, &image_), "vkCreateImage " + desc.name);

  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(context.device(), image_, &requirements);
  try {
    allocation_ = context.allocator().allocate(requirements, MemoryUsage::gpu_only, ResourceTiling::optimal);
    check(vkBindImageMemory(context.device(), image_, allocation_.memory, allocation_.offset),
          "vkBindImageMemory " + desc.name);
    VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view_info.image = image_;
    view_info.viewType = desc.view_type;
    view_info.format = desc.format;
    view_info.subresourceRange = {aspect_of(desc.format), 0, desc.mip_levels, 0, desc.array_layers};
    check(vkCreateImageView(context.device(), &view_info, nullptr, &view_), "vkCreateImageView " + desc.name);
    views_ = std::make_unique<ImageViewCache>(context.device(), image_, desc.format);
  } catch (...) {
    reset();
    throw;
  }
  if (!desc.name.empty()) {
    context.set_name(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(image_), desc.name.c_str());
  }
}

Image::~Image() { reset(); }

Image::Image(Image&& other) noexcept
    : context_(std::exchange(other.context_, nullptr)),
      image_(std::exchange(other.image_, VK_NULL_HANDLE)),
      view_(std::exchange(other.view_, VK_NULL_HANDLE)),
      views_(std::move(other.views_)),
      allocation_(std::exchange(other.allocation_, {})),
      format_(other.format_),
      extent_(other.extent_),
      mip_levels_(other.mip_levels_),
      array_layers_(other.array_layers_),
      cube_compatible_(other.cube_compatible_),
      serial_(std::exchange(other.serial_, 0)) {}

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    reset();
    context_ = std::exchange(other.context_, nullptr);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    views_ = std::move(other.views_);
    allocation_ = std::exchange(other.allocation_, {});
    format_ = other.format_;
    extent_ = other.extent_;
    mip_levels_ = other.mip_levels_;
    array_layers_ = other.array_layers_;
    cube_compatible_ = other.cube_compatible_;
    serial_ = std::exchange(other.serial_, 0);
  }
  return *this;
}

VkImageAspectFlags Image::aspect() const { return aspect_of(format_); }

void Image::reset() {
  if (image_ == VK_NULL_HANDLE) return;
  views_.reset();
  if (view_ != VK_NULL_HANDLE) vkDestroyImageView(context_->device(), view_, nullptr);
  vkDestroyImage(context_->device(), image_, nullptr);
  context_->allocator().free(allocation_);  // no-op for an allocation never made
  image_ = VK_NULL_HANDLE;
  view_ = VK_NULL_HANDLE;
  allocation_ = {};
}

}  // namespace sg::vk
