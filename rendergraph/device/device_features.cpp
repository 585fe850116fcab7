// SPDX-License-Identifier: MIT
#include "rendergraph/device/device_features.h"

namespace sg::vk {
namespace {

struct RequiredFeature {
  const char* name;
  const char* why;
  VkBool32& (*field)(DeviceFeatures&);
};

constexpr RequiredFeature required_features[] = {
    {"dynamicRendering (Vulkan 1.3)", "raster passes begin rendering from declared attachments",
     [](DeviceFeatures& f) -> VkBool32& { return f.v13.dynamicRendering; }},
    {"synchronization2 (Vulkan 1.3)", "the render graph emits vkCmdPipelineBarrier2",
     [](DeviceFeatures& f) -> VkBool32& { return f.v13.synchronization2; }},
    {"shaderClipDistance", "shadow views drawn into atlas tiles are clipped to their own frustum",
     [](DeviceFeatures& f) -> VkBool32& { return f.core.features.shaderClipDistance; }},
    {"multiDrawIndirect", "casters are drawn with one indirect call per light view",
     [](DeviceFeatures& f) -> VkBool32& { return f.core.features.multiDrawIndirect; }},
    {"drawIndirectFirstInstance", "indirect draws index per-instance data",
     [](DeviceFeatures& f) -> VkBool32& { return f.core.features.drawIndirectFirstInstance; }},
    {"shaderDrawParameters (Vulkan 1.1)", "shaders read gl_DrawID and gl_BaseInstance",
     [](DeviceFeatures& f) -> VkBool32& { return f.v11.shaderDrawParameters; }},
    {"timelineSemaphore (Vulkan 1.2)",
     "a frame may wait for a value the host signals later (SemaphoreWait::value)",
     [](DeviceFeatures& f) -> VkBool32& { return f.v12.timelineSemaphore; }},
    {"maintenance4 (Vulkan 1.3)",
     "compute shaders compiled for SPIR-V 1.6 declare their workgroup size with LocalSizeId",
     [](DeviceFeatures& f) -> VkBool32& { return f.v13.maintenance4; }},
};

}  // namespace

DeviceFeatures::DeviceFeatures() {
  core.pNext = &v11;
  v11.pNext = &v12;
  v12.pNext = &v13;
}

void query_features(VkPhysicalDevice device, DeviceFeatures& out) {
  vkGetPhysicalDeviceFeatures2(device, &out.core);
}

std::vector<std::string> missing_required_features(DeviceFeatures& supported) {
  std::vector<std::string> missing;
  for (const RequiredFeature& r : required_features) {
    if (!r.field(supported)) missing.push_back(std::string(r.name) + ", needed because " + r.why);
  }
  return missing;
}

void enable_required_features(DeviceFeatures& out) {
  for (const RequiredFeature& r : required_features) r.field(out) = VK_TRUE;
}

OptionalFeatures enable_optional_features(const DeviceFeatures& supported, DeviceFeatures& out) {
  OptionalFeatures enabled;
  enabled.shader_output_layer = supported.v12.shaderOutputLayer == VK_TRUE;
  out.v12.shaderOutputLayer = supported.v12.shaderOutputLayer;
  return enabled;
}

}  // namespace sg::vk
