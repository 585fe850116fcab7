// SPDX-License-Identifier: MIT
#include "systems/lighting/light_resources.h"

#include <stdexcept>

#include "rendergraph/device/context.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/shadow_maps/shadow_atlas.h"

namespace sg {
namespace {

LightRecordsIn resolved(LightRecordsIn records, const vk::VulkanContext& context) {
  if (records != LightRecordsIn::automatic) return records;
  return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? LightRecordsIn::texel_buffer
                                                                        : LightRecordsIn::storage_buffer;
}

}  // namespace

VkFilter comparison_filter(VkFormatFeatureFlags features) {
  return (features & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0 ? VK_FILTER_LINEAR
                                                                             : VK_FILTER_NEAREST;
}

bool shadow_comparisons_filter(const vk::VulkanContext& context) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), vk::to_vk(ShadowAtlas::depth_format),
                                      &properties);
  return comparison_filter(properties.optimalTilingFeatures) == VK_FILTER_LINEAR;
}

LightResources::LightResources(const vk::VulkanContext& context, LightRecordsIn records)
    : records_(resolved(records, context)),
      nearest_comparisons_(!shadow_comparisons_filter(context)),
      nearest_(vk::create_sampler(context.device(), VK_FILTER_NEAREST)),
      compare_(vk::create_sampler(context.device(),
                                  nearest_comparisons_ ? VK_FILTER_NEAREST : VK_FILTER_LINEAR, true)) {}

std::vector<uint32_t> LightResources::specialized(std::vector<uint32_t> constants) const {
  constexpr size_t light_types_constant = 3;
  constexpr size_t nearest_comparisons_constant = 10;
  if (constants.size() <= light_types_constant) {
    throw std::logic_error(
        "LightResources::specialized: the constants must reach LIGHT_TYPES (constant_id 3)");
  }
  if (constants.size() <= nearest_comparisons_constant)
    constants.resize(nearest_comparisons_constant + 1, 0u);
  constants[nearest_comparisons_constant] = nearest_comparisons_ ? 1u : 0u;
  return constants;
}

std::vector<VkDescriptorSetLayoutBinding> LightResources::bindings(
    LightRecordsIn records, VkShaderStageFlags stages, std::vector<VkDescriptorSetLayoutBinding> more) {
  using namespace bindings;
  const VkDescriptorType records_type = records == LightRecordsIn::storage_buffer
                                            ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
                                            : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
  more.insert(more.begin(),
              {{lights_binding, records_type, 1, stages},
               {shadow_maps_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages},
               {shadow_maps_compare_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages}});
  return more;
}

vk::DescriptorWriter& LightResources::write(vk::DescriptorWriter& writer, const vk::Buffer& lights,
                                            VkImageView atlas) const {
  using namespace bindings;
  if (records_ == LightRecordsIn::storage_buffer) {
    writer.buffer(lights_binding, lights.handle());
  } else {
    writer.texel_buffer(lights_binding, lights.texel_view());
  }
  return writer.image(shadow_maps_binding, atlas, nearest_.get())
      .image(shadow_maps_compare_binding, atlas, compare_.get());
}

vk::DescriptorWriter& LightResources::write(vk::DescriptorWriter& writer, const vk::Buffer& lights,
                                            const vk::PassRecorder& rec, rg::ImageHandle atlas) const {
  return write(writer, lights, rec.view(atlas, rg::SubresourceRange::all(), VK_IMAGE_VIEW_TYPE_2D_ARRAY));
}

}  // namespace sg
