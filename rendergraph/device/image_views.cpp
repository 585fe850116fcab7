#include "rendergraph/device/image_views.h"

#include "rendergraph/device/resources.h"
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

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
