// SPDX-License-Identifier: MIT
#pragma once
// The device features the engine needs, as one table: adding a requirement is one line, and
// a device that lacks one is rejected with the feature's name in the message.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::vk {

// VkPhysicalDeviceFeatures2 with its 1.1-1.3 chain linked; not copyable (pNext points inside).
struct DeviceFeatures {
  VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};

  DeviceFeatures();
  DeviceFeatures(const DeviceFeatures&) = delete;
  DeviceFeatures& operator=(const DeviceFeatures&) = delete;
};

// Queries what `device` supports.
void query_features(VkPhysicalDevice device, DeviceFeatures& out);
// Names of the required features that `supported` lacks; empty when the device qualifies.
std::vector<std::string> missing_required_features(DeviceFeatures& supported);
// Sets exactly the required features in `out` (for VkDeviceCreateInfo::pNext).
void enable_required_features(DeviceFeatures& out);

// Features the engine uses when present and works around when absent.
struct OptionalFeatures {
  // shaderOutputLayer (Vulkan 1.2): gl_Layer from the vertex shader, for drawing every shadow
  // view into its atlas layer at once; without it shadow views render one pass each.
  bool shader_output_layer = false;
};
// Sets in `out` the optional features that `supported` has, and says which.
OptionalFeatures enable_optional_features(const DeviceFeatures& supported, DeviceFeatures& out);

}  // namespace sg::vk
