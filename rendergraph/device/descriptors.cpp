// SPDX-License-Identifier: MIT
#include "rendergraph/device/descriptors.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {
namespace {

bool is_image(VkDescriptorType type) {
  return type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER || type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE ||
         type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE || type == VK_DESCRIPTOR_TYPE_SAMPLER;
}

bool is_texel_buffer(VkDescriptorType type) {
  return type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER || type == VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
}

}  // namespace

PipelineLayout::PipelineLayout(VkDevice device, std::vector<VkDescriptorSetLayoutBinding> bindings,
                               VkPushConstantRange push)
    : device_(device), bindings_(std::move(bindings)), push_(push) {
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = static_cast<uint32_t>(bindings_.size());
  set_info.pBindings = bindings_.data();
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout), "vkCreateDescriptorSetLayout");
  set_layout_ = UniqueDescriptorSetLayout(device, set_layout);

  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = 1;
  info.pSetLayouts = &set_layout;
  info.pushConstantRangeCount = push_.size > 0 ? 1 : 0;
  info.pPushConstantRanges = &push_;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  check(vkCreatePipelineLayout(device, &info, nullptr, &layout), "vkCreatePipelineLayout");
  layout_ = UniquePipelineLayout(device, layout);
}

VkDescriptorType PipelineLayout::type_of(uint32_t binding) const {
  const auto found =
      std::find_if(bindings_.begin(), bindings_.end(),
                   [&](const VkDescriptorSetLayoutBinding& b) { return b.binding == binding; });
  if (found == bindings_.end()) {
    throw std::logic_error("descriptor binding " + std::to_string(binding) + " is not in the layout");
  }
  return found->descriptorType;
}

DescriptorSets PipelineLayout::allocate_sets(uint32_t count) const {
  std::vector<VkDescriptorPoolSize> sizes;
  for (const VkDescriptorSetLayoutBinding& binding : bindings_) {
    sizes.push_back({binding.descriptorType, binding.descriptorCount * count});
  }
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = count;
  pool_info.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  check(vkCreateDescriptorPool(device_, &pool_info, nullptr, &pool), "vkCreateDescriptorPool");
  DescriptorSets result{UniqueDescriptorPool(device_, pool), std::vector<VkDescriptorSet>(count)};
  const std::vector<VkDescriptorSetLayout> layouts(count, set_layout_.get());
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = count;
  alloc.pSetLayouts = layouts.data();
  check(vkAllocateDescriptorSets(device_, &alloc, result.sets.data()), "vkAllocateDescriptorSets");
  return result;
}

DescriptorWriter PipelineLayout::write(VkDescriptorSet set) const { return DescriptorWriter(*this, set); }

void PipelineLayout::bind(VkCommandBuffer cmd, VkDescriptorSet set,
                          std::span<const uint32_t> dynamic_offsets) const {
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1, &set,
                          static_cast<uint32_t>(dynamic_offsets.size()), dynamic_offsets.data());
}

void PipelineLayout::bind_compute(VkCommandBuffer cmd, VkDescriptorSet set) const {
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 1, &set, 0, nullptr);
}

void PipelineLayout::push_bytes(VkCommandBuffer cmd, const void* data, uint32_t size) const {
  if (size > push_.size) {
    throw std::logic_error("pushing " + std::to_string(size) + " bytes into a push-constant range of " +
                           std::to_string(push_.size));
  }
  vkCmdPushConstants(cmd, layout_.get(), push_.stageFlags, 0, size, data);
}

DescriptorWriter::Write& DescriptorWriter::add(uint32_t binding) {
  if (count_ == max_writes) throw std::logic_error("more descriptor writes than DescriptorWriter holds");
  Write& write = writes_[count_++];
  write = {binding, {}, {}, VK_NULL_HANDLE};
  return write;
}

DescriptorWriter& DescriptorWriter::buffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                                           VkDeviceSize range) {
  const VkDescriptorType type = layout_.type_of(binding);
  if (is_image(type) || is_texel_buffer(type)) {
    throw std::logic_error("descriptor binding " + std::to_string(binding) +
                           " takes an image or a texel buffer view, not a buffer");
  }
  add(binding).buffer = {buffer, offset, range};
  return *this;
}

DescriptorWriter& DescriptorWriter::texel_buffer(uint32_t binding, VkBufferView view) {
  if (!is_texel_buffer(layout_.type_of(binding))) {
    throw std::logic_error("descriptor binding " + std::to_string(binding) + " takes no texel buffer view");
  }
  add(binding).texel_view = view;
  return *this;
}

DescriptorWriter& DescriptorWriter::image(uint32_t binding, VkImageView view, VkSampler sampler,
                                          VkImageLayout layout) {
  if (!is_image(layout_.type_of(binding))) {
    throw std::logic_error("descriptor binding " + std::to_string(binding) + " takes a buffer, not an image");
  }
  add(binding).image = {sampler, view, layout};
  return *this;
}

VkDescriptorSet DescriptorWriter::update() {
  std::array<VkWriteDescriptorSet, max_writes> vk_writes;
  for (size_t i = 0; i < count_; ++i) {
    const Write& write = writes_[i];
    VkWriteDescriptorSet& out = vk_writes[i];
    out = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    out.dstSet = set_;
    out.dstBinding = write.binding;
    out.descriptorCount = 1;
    out.descriptorType = layout_.type_of(write.binding);
    if (is_image(out.descriptorType)) {
      out.pImageInfo = &write.image;
    } else if (is_texel_buffer(out.descriptorType)) {
      out.pTexelBufferView = &write.texel_view;
    } else {
      out.pBufferInfo = &write.buffer;
    }
  }
  vkUpdateDescriptorSets(layout_.device_, static_cast<uint32_t>(count_), vk_writes.data(), 0, nullptr);
  count_ = 0;
  return set_;
}

UniqueSampler create_sampler(VkDevice device, VkFilter filter, bool compare, VkSamplerAddressMode address) {
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

}  // namespace sg::vk
