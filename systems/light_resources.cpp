#include "systems/light_resources.h"

#include "rendergraph/device/context.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "systems/shader_bindings.h"
#include "systems/shadow_map_arrays.h"

namespace sg {
namespace {

VkFilter compare_filter(const vk::VulkanContext& context) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), vk::to_vk(ShadowMapArrays::depth_format),
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
              {{lights_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages},
               {shadow_maps_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages},
               {shadow_maps_compare_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages},
               {shadow_cubes_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages}});
  return more;
}

vk::DescriptorWriter& LightResources::write(vk::DescriptorWriter& writer, VkBuffer lights, VkImageView maps,
                                            VkImageView cubes) const {
  using namespace bindings;
  return writer.buffer(lights_binding, lights)
      .image(shadow_maps_binding, maps, nearest_.get())
      .image(shadow_maps_compare_binding, maps, compare_.get())
      .image(shadow_cubes_binding, cubes, nearest_.get());
}

vk::DescriptorWriter& LightResources::write(vk::DescriptorWriter& writer, VkBuffer lights,
                                            const vk::PassRecorder& rec, rg::ImageHandle maps,
                                            rg::ImageHandle cubes) const {
  return write(writer, lights, rec.view(maps, rg::SubresourceRange::all(), VK_IMAGE_VIEW_TYPE_2D_ARRAY),
               rec.view(cubes, rg::SubresourceRange::all(), VK_IMAGE_VIEW_TYPE_CUBE_ARRAY));
}

}  // namespace sg
