// SPDX-License-Identifier: MIT
#include "rendergraph/device/swapchain.h"

#include <algorithm>

#include "rendergraph/device/context.h"
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {
namespace {

VkSurfaceFormatKHR choose_format(VkPhysicalDevice device, VkSurfaceKHR surface) {
  uint32_t count = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(count);
  vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data());
  if (formats.empty()) throw VulkanError("the window surface offers no image formats");
  // Shading is linear; an sRGB image makes the hardware encode on write, as the headless
  // path's sRGB offscreen image does, so both paths produce the same pixels.
  for (const VkSurfaceFormatKHR& f : formats) {
    if ((f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB) &&
        f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
      return f;
    }
  }
  return formats.front();
}

VkPresentModeKHR choose_present_mode(VkPhysicalDevice device, VkSurfaceKHR surface, PresentMode mode) {
  if (mode == PresentMode::vsync) return VK_PRESENT_MODE_FIFO_KHR;  // always supported
  uint32_t count = 0;
  vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &count, nullptr);
  std::vector<VkPresentModeKHR> modes(count);
  vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &count, modes.data());
  for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR}) {
    if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  }
  return VK_PRESENT_MODE_FIFO_KHR;
}

}  // namespace

Swapchain::Swapchain(VulkanContext& context, VkSurfaceKHR surface, PresentMode mode)
    : context_(context), surface_(surface), mode_(mode) {
  VkBool32 supported = VK_FALSE;
  vkGetPhysicalDeviceSurfaceSupportKHR(context.physical_device(), context.queue_family(), surface,
                                       &supported);
  if (!supported) {
    vkDestroySurfaceKHR(context.instance(), surface_, nullptr);
    throw VulkanError("the device's graphics queue cannot present to this window");
  }
  format_ = choose_format(context.physical_device(), surface);
}

Swapchain::~Swapchain() {
  vkDeviceWaitIdle(context_.device());
  destroy_swapchain();
  vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
}

void Swapchain::destroy_swapchain() {
  if (swapchain_ == VK_NULL_HANDLE) return;
  vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
  swapchain_ = VK_NULL_HANDLE;
  images_.clear();
  render_finished_.clear();
}

bool Swapchain::recreate(VkExtent2D wanted) {
  // Resizes are rare; waiting for idle is simpler than tracking which frame holds which image.
  vkDeviceWaitIdle(context_.device());
  VkSurfaceCapabilitiesKHR caps;
  check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physical_device(), surface_, &caps),
        "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == UINT32_MAX) {  // the surface takes its size from the swapchain
    extent.width = std::clamp(wanted.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height = std::clamp(wanted.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (extent.width == 0 || extent.height == 0 || wanted.width == 0 || wanted.height == 0) {
    destroy_swapchain();
    return false;
  }
  constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if ((caps.supportedUsageFlags & usage) != usage) {
    throw VulkanError("the window surface does not allow transfer-destination color images");
  }

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) info.minImageCount = std::min(info.minImageCount, caps.maxImageCount);
  info.imageFormat = format_.format;
  info.imageColorSpace = format_.colorSpace;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = usage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)) {
    info.compositeAlpha = static_cast<VkCompositeAlphaFlagBitsKHR>(
        caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);  // lowest supported bit
  }
  info.presentMode = choose_present_mode(context_.physical_device(), surface_, mode_);
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  check(vkCreateSwapchainKHR(context_.device(), &info, nullptr, &created), "vkCreateSwapchainKHR");
  destroy_swapchain();
  swapchain_ = created;
  extent_ = extent;

  uint32_t count = 0;
  vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, nullptr);
  images_.resize(count);
  vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, images_.data());
  for (uint32_t i = 0; i < count; ++i) {
    VkSemaphoreCreateInfo sem_info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore;
    check(vkCreateSemaphore(context_.device(), &sem_info, nullptr, &semaphore), "vkCreateSemaphore");
    render_finished_.emplace_back(context_.device(), semaphore);
  }
  return true;
}

std::optional<uint32_t> Swapchain::acquire(VkSemaphore image_acquired) {
  uint32_t index = 0;
  const VkResult result = vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX, image_acquired,
                                                VK_NULL_HANDLE, &index);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt;
  if (result != VK_SUBOPTIMAL_KHR) check(result, "vkAcquireNextImageKHR");
  return index;
}

bool Swapchain::present(uint32_t index) {
  const VkSemaphore wait = render_finished(index);
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &wait;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &index;
  const VkResult result = vkQueuePresentKHR(context_.queue(), &info);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
  check(result, "vkQueuePresentKHR");
  return true;
}

}  // namespace sg::vk
