// SPDX-License-Identifier: MIT
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

std::string_view to_string(VkResult result) {
  switch (result) {
#define SG_RESULT(name) \
  case name: return #name;
    SG_RESULT(VK_SUCCESS)
    SG_RESULT(VK_NOT_READY)
    SG_RESULT(VK_TIMEOUT)
    SG_RESULT(VK_INCOMPLETE)
    SG_RESULT(VK_SUBOPTIMAL_KHR)
    SG_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    SG_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    SG_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    SG_RESULT(VK_ERROR_DEVICE_LOST)
    SG_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    SG_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    SG_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    SG_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    SG_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    SG_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    SG_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    SG_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    SG_RESULT(VK_ERROR_SURFACE_LOST_KHR)
    SG_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    SG_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
    SG_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
#undef SG_RESULT
    default: return "unknown VkResult";
  }
}

void check(VkResult result, std::string_view what) {
  if (result == VK_SUCCESS) return;
  throw VulkanError(std::string(what) + " failed: " + std::string(to_string(result)) + " (" +
                    std::to_string(static_cast<int>(result)) + ")");
}

}  // namespace sg::vk
