// SPDX-License-Identifier: MIT
#pragma once
// What a pass binds, declared once. A PipelineLayout is one descriptor set layout and at most
// one push-constant range, kept with the bindings it was made from, so that writing a set names
// only binding numbers (each write takes its descriptor type from the layout):
//
//   const vk::PipelineLayout layout(device, {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
//                                             VK_SHADER_STAGE_FRAGMENT_BIT}},
//                                   vk::push_constants<Lens>(VK_SHADER_STAGE_FRAGMENT_BIT));
//   const VkDescriptorSet set = layout.write(rec.allocate_set(layout))
//                                   .image(0, view, sampler)
//                                   .update();
//   layout.bind(cmd, set);
//   layout.push(cmd, lens);
//
// Pipelines are made with layout.get(). Samplers are here too: every pass that samples makes them
// the same way.
#include <array>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/unique_handle.h"

namespace sg::vk {

class DescriptorWriter;

// One descriptor set per frame in flight, in a pool of their own: a pass that rewrites its set
// every frame keeps one per frame slot, so the GPU never reads a set the CPU is updating.
struct DescriptorSets {
  UniqueDescriptorPool pool;
  std::vector<VkDescriptorSet> sets;
};

// The push-constant range of a struct, from offset 0.
template <class Constants>
constexpr VkPushConstantRange push_constants(VkShaderStageFlags stages) {
  static_assert(sizeof(Constants) <= 128, "Vulkan guarantees only 128 bytes of push constants");
  return {stages, 0, static_cast<uint32_t>(sizeof(Constants))};
}

class PipelineLayout {
 public:
  PipelineLayout() = default;
  // `push` of size 0: no push constants.
  PipelineLayout(VkDevice device, std::vector<VkDescriptorSetLayoutBinding> bindings,
                 VkPushConstantRange push = {});

  VkPipelineLayout get() const { return layout_.get(); }
  VkDescriptorSetLayout set_layout() const { return set_layout_.get(); }
  // Throws std::logic_error for a binding the layout does not declare.
  VkDescriptorType type_of(uint32_t binding) const;

  DescriptorSets allocate_sets(uint32_t count) const;
  DescriptorWriter write(VkDescriptorSet set) const;

  // Binds `set` as set 0 of graphics pipelines; `dynamic_offsets` are its dynamic buffers',
  // in binding order.
  void bind(VkCommandBuffer cmd, VkDescriptorSet set, std::span<const uint32_t> dynamic_offsets = {}) const;
  // Binds `set` as set 0 of compute pipelines.
  void bind_compute(VkCommandBuffer cmd, VkDescriptorSet set) const;
  // Pushes `constants` at offset 0, to the stages of the layout's push-constant range.
  template <class Constants>
  void push(VkCommandBuffer cmd, const Constants& constants) const {
    static_assert(std::is_trivially_copyable_v<Constants>);
    push_bytes(cmd, &constants, sizeof(Constants));
  }

 private:
  friend class DescriptorWriter;
  // Throws std::logic_error when `size` exceeds the push-constant range.
  void push_bytes(VkCommandBuffer cmd, const void* data, uint32_t size) const;

  VkDevice device_ = VK_NULL_HANDLE;
  std::vector<VkDescriptorSetLayoutBinding> bindings_;
  VkPushConstantRange push_{};
  UniqueDescriptorSetLayout set_layout_;
  UniquePipelineLayout layout_;
};

// Collects writes to one descriptor set and applies them with one vkUpdateDescriptorSets.
// Made by PipelineLayout::write; must not outlive the layout.
class DescriptorWriter {
 public:
  DescriptorWriter& buffer(uint32_t binding, VkBuffer buffer, VkDeviceSize offset = 0,
                           VkDeviceSize range = VK_WHOLE_SIZE);
  // A view of a buffer made with a texel_format (Buffer::texel_view).
  DescriptorWriter& texel_buffer(uint32_t binding, VkBufferView view);
  // The layout is the one the render graph gives sampled images.
  DescriptorWriter& image(uint32_t binding, VkImageView view, VkSampler sampler,
                          VkImageLayout layout = VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
  // Writes everything collected; returns the set, for binding.
  VkDescriptorSet update();

 private:
  friend class PipelineLayout;
  DescriptorWriter(const PipelineLayout& layout, VkDescriptorSet set) : layout_(layout), set_(set) {}

  struct Write {
    uint32_t binding;
    VkDescriptorBufferInfo buffer;
    VkDescriptorImageInfo image;
    VkBufferView texel_view;
  };
  Write& add(uint32_t binding);

  static constexpr size_t max_writes = 16;
  const PipelineLayout& layout_;
  VkDescriptorSet set_;
  std::array<Write, max_writes> writes_{};
  size_t count_ = 0;
};

// One mip level. `compare` makes a depth-comparison sampler with VK_COMPARE_OP_LESS_OR_EQUAL
// (1 where the reference is not farther than the texel).
UniqueSampler create_sampler(VkDevice device, VkFilter filter, bool compare = false,
                             VkSamplerAddressMode address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);

}  // namespace sg::vk
