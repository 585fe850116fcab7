// SPDX-License-Identifier: MIT
#pragma once
// The window's swapchain. It is recreated, never patched, when the window's framebuffer size
// changes or the presentation engine reports it out of date; a minimized window (zero extent)
// has no swapchain, and the caller skips frames until it is restored.
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/unique_handle.h"

namespace sg::vk {

class VulkanContext;

enum class PresentMode { vsync, no_vsync };

class Swapchain {
 public:
  // Takes ownership of `surface`.
  Swapchain(VulkanContext& context, VkSurfaceKHR surface, PresentMode mode);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // (Re)creates the images for a framebuffer of `extent`, clamped to what the surface allows.
  // Waits for the device to go idle first, so no frame still uses the old images (or anything
  // sized to them). Returns false for a zero extent (minimized window): nothing to render to.
  bool recreate(VkExtent2D extent);

  // Index of the next image, signalling `image_acquired` when it may be written; nothing when
  // the swapchain is out of date and must be recreated.
  std::optional<uint32_t> acquire(VkSemaphore image_acquired);
  // Presents `index` once render_finished(index) is signalled. False when the swapchain must
  // be recreated (out of date or suboptimal).
  bool present(uint32_t index);

  // Signalled by the frame that renders into image `index`; one per image, as the
  // presentation engine may still hold an earlier frame's semaphore.
  VkSemaphore render_finished(uint32_t index) const { return render_finished_[index].get(); }
  VkImage image(uint32_t index) const { return images_[index]; }
  VkFormat format() const { return format_.format; }
  VkExtent2D extent() const { return extent_; }
  bool valid() const { return swapchain_ != VK_NULL_HANDLE; }

 private:
  void destroy_swapchain();

  VulkanContext& context_;
  VkSurfaceKHR surface_;
  PresentMode mode_;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkSurfaceFormatKHR format_{};
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  std::vector<UniqueSemaphore> render_finished_;
};

}  // namespace sg::vk
