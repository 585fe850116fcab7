// SPDX-License-Identifier: MIT
#pragma once
// Move-only owner of a device-level Vulkan object, destroyed with the matching vkDestroy*.
//   UniqueHandle<VkPipeline, vkDestroyPipeline> pipeline{device, handle};
#include <utility>

#include <vulkan/vulkan.h>

namespace sg::vk {

template <class T, void (*Destroy)(VkDevice, T, const VkAllocationCallbacks*)>
class UniqueHandle {
 public:
  UniqueHandle() = default;
  UniqueHandle(VkDevice device, T handle) : device_(device), handle_(handle) {}
  ~UniqueHandle() { reset(); }
  UniqueHandle(UniqueHandle&& o) noexcept
      : device_(o.device_), handle_(std::exchange(o.handle_, VK_NULL_HANDLE)) {}
  UniqueHandle& operator=(UniqueHandle&& o) noexcept {
    if (this != &o) {
      reset();
      device_ = o.device_;
      handle_ = std::exchange(o.handle_, VK_NULL_HANDLE);
    }
    return *this;
  }

  T get() const { return handle_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }
  void reset() {
    if (handle_ != VK_NULL_HANDLE) Destroy(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  T handle_ = VK_NULL_HANDLE;
};

using UniquePipeline = UniqueHandle<VkPipeline, vkDestroyPipeline>;
using UniquePipelineLayout = UniqueHandle<VkPipelineLayout, vkDestroyPipelineLayout>;
using UniqueDescriptorSetLayout = UniqueHandle<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using UniqueDescriptorPool = UniqueHandle<VkDescriptorPool, vkDestroyDescriptorPool>;
using UniqueShaderModule = UniqueHandle<VkShaderModule, vkDestroyShaderModule>;
using UniqueCommandPool = UniqueHandle<VkCommandPool, vkDestroyCommandPool>;
using UniqueFence = UniqueHandle<VkFence, vkDestroyFence>;
using UniqueSemaphore = UniqueHandle<VkSemaphore, vkDestroySemaphore>;
using UniqueImageView = UniqueHandle<VkImageView, vkDestroyImageView>;
using UniqueSampler = UniqueHandle<VkSampler, vkDestroySampler>;

}  // namespace sg::vk
