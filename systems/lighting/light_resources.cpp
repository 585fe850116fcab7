// SPDX-License-Identifier: MIT
#include "systems/lighting/light_resources.h"

#include "rendergraph/device/context.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/shadow_maps/shadow_atlas.h"

namespace sg {
namespace {

VkFilter compare_filter(const vk::VulkanContext& context) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), vk::to_vk(ShadowAtlas::depth_format),
                                      &properties);
  const bool filterable =
      properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  return filterable ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
}

}  // namespace

LightResources::LightResources(const vk::VulkanContext& context)
    : nearest_(vk::create_sampler(context.device(), VK_FILTER_NEAREST)),
      compare_(vk::create_sampler(context.device(), compare_filter(context), true)) {}

std::vector<VkDescriptorSetLayoutBinding> LightResources::bindings(
    VkShaderStageFlags stages, std::vector<VkDescriptorSetLayoutBinding> more) {
  using namespace bindings;
  more.insert(more.begin(),
              {{lights_binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 1, stages},
               {shadow_maps_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages},
               {shadow_maps_compare_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages}});
  return more;
}

vk::DescriptorWriter& LightResources::write(vk::DescriptorWriter& writer, VkBufferView lights,
                                            VkImageView atlas) const {
  using namespace bindings;
  return writer.texel_buffer(lights_binding, lights)
      .image(shadow_maps_binding, atlas, nearest_.get())
      .image(shadow_maps_compare_binding, atlas, compare_.get());
}

vk::DescriptorWriter& LightResources::write(vk::DescriptorWriter& writer, VkBufferView lights,
                                            const vk::PassRecorder& rec, rg::ImageHandle atlas) const {
  return write(writer, lights, rec.view(atlas, rg::SubresourceRange::all(), VK_IMAGE_VIEW_TYPE_2D_ARRAY));
}

}  // namespace sg
