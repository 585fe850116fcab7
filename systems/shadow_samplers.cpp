#include "systems/shadow_samplers.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "systems/shadow_map_arrays.h"

namespace sg {

ShadowSamplers create_shadow_samplers(const vk::VulkanContext& context) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), vk::to_vk(ShadowMapArrays::depth_format),
                                      &properties);
  const bool filterable =
      properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  return {vk::create_sampler(context.device(), VK_FILTER_NEAREST),
          vk::create_sampler(context.device(), filterable ? VK_FILTER_LINEAR : VK_FILTER_NEAREST, true)};
}

}  // namespace sg
