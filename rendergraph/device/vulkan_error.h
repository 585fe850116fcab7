// SPDX-License-Identifier: MIT
#pragma once
// Errors from the Vulkan layer are exceptions carrying a message a user can act on
// (what failed, and why); the sandbox prints them and exits non-zero.
#include <stdexcept>
#include <string>
#include <string_view>

#include <vulkan/vulkan.h>

namespace sg::vk {

class VulkanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Name of a VkResult, e.g. "VK_ERROR_OUT_OF_DEVICE_MEMORY".
std::string_view to_string(VkResult result);

// Throws VulkanError("<what> failed: <result>") unless result is VK_SUCCESS.
void check(VkResult result, std::string_view what);

}  // namespace sg::vk
