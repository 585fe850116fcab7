// SPDX-License-Identifier: MIT
#include "rendergraph/device/image_views.h"

#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

VkImageAspectFlags aspect_of(VkFormat format) {
  switch (format) {
    case VK_FORMAT_D16_UNORM:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_X8_D24_UNORM_PACK32: return VK_IMAGE_ASPECT_DEPTH_BIT;
    case VK_FORMAT_D16_UNORM_S8_UINT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT: return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    default: return VK_IMAGE_ASPECT_COLOR_BIT;
  }
}

ImageViewCache::ImageViewCache(VkDevice device, VkImage image, VkFormat format)
    : device_(device), image_(image), format_(format) {}

ImageViewCache::~ImageViewCache() {
  for (const Entry& entry : views_) vkDestroyImageView(device_, entry.view, nullptr);
}

VkImageView ImageViewCache::get(const ViewKey& key) {
  for (const Entry& entry : views_) {
    if (entry.key == key) return entry.view;
  }
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image_;
  info.viewType = key.type;
  info.format = format_;
  info.subresourceRange = {aspect_of(format_), key.base_mip, key.mip_count, key.base_layer, key.layer_count};
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(device_, &info, nullptr, &view), "vkCreateImageView");
  views_.push_back({key, view});
  return view;
}

}  // namespace sg::vk
