#include "rendergraph/device/descriptors.h"

#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

UniqueDescriptorSetLayout create_set_layout(VkDevice device,
                                            std::span<const VkDescriptorSetLayoutBinding> bindings) {
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout), "vkCreateDescriptorSetLayout");
  return UniqueDescriptorSetLayout(device, layout);
}

UniquePipelineLayout create_pipeline_layout(VkDevice device, VkDescriptorSetLayout set_layout,
                                            VkPushConstantRange push) {
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = 1;
  info.pSetLayouts = &set_layout;
  info.pushConstantRangeCount = push.size > 0 ? 1 : 0;
  info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  check(vkCreatePipelineLayout(device, &info, nullptr, &layout), "vkCreatePipelineLayout");
  return UniquePipelineLayout(device, layout);
}

UniqueSampler create_sampler(VkDevice device, VkFilter filter, bool compare,
                             VkSamplerAddressMode address) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = address;
  info.addressModeV = address;
  info.addressModeW = address;
  info.compareEnable = compare ? VK_TRUE : VK_FALSE;
  info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(device, &info, nullptr, &sampler), "vkCreateSampler");
  return UniqueSampler(device, sampler);
}

DescriptorSets allocate_sets(VkDevice device, VkDescriptorSetLayout layout,
                             std::span<const VkDescriptorSetLayoutBinding> bindings, uint32_t count) {
  std::vector<VkDescriptorPoolSize> sizes;
  for (const VkDescriptorSetLayoutBinding& binding : bindings) {
    sizes.push_back({binding.descriptorType, binding.descriptorCount * count});
  }
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = count;
  pool_info.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  check(vkCreateDescriptorPool(device, &pool_info, nullptr, &pool), "vkCreateDescriptorPool");
  DescriptorSets result{UniqueDescriptorPool(device, pool), std::vector<VkDescriptorSet>(count)};
  const std::vector<VkDescriptorSetLayout> layouts(count, layout);
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = count;
  alloc.pSetLayouts = layouts.data();
  check(vkAllocateDescriptorSets(device, &alloc, result.sets.data()), "vkAllocateDescriptorSets");
  return result;
}

}  // namespace sg::vk
