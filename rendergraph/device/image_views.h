// SPDX-License-Identifier: MIT
#pragma once
// Views of parts of one image, created on first use and kept until the image goes away. Passes
// ask for views of exactly the subresources they declared (one cube face, one atlas layer, a
// mip), so an image may need many; creating each once keeps view creation out of the frame.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::vk {

// Depth, stencil or color aspect of a format.
VkImageAspectFlags aspect_of(VkFormat format);

struct ViewKey {
  uint32_t base_mip = 0;
  uint32_t mip_count = 1;
  uint32_t base_layer = 0;
  uint32_t layer_count = 1;
  VkImageViewType type = VK_IMAGE_VIEW_TYPE_2D;

  friend bool operator==(const ViewKey&, const ViewKey&) = default;
};

class ImageViewCache {
 public:
  ImageViewCache(VkDevice device, VkImage image, VkFormat format);
  ~ImageViewCache();
  ImageViewCache(const ImageViewCache&) = delete;
  ImageViewCache& operator=(const ImageViewCache&) = delete;

  // Throws VulkanError when the view cannot be created (for example a cube view of a range
  // that is not a multiple of six layers).
  VkImageView get(const ViewKey& key);

  VkFormat format() const { return format_; }

 private:
  struct Entry {
    ViewKey key;
    VkImageView view;
  };

  VkDevice device_;
  VkImage image_;
  VkFormat format_;
  std::vector<Entry> views_;  // few per image: a linear search beats hashing
};

}  // namespace sg::vk
