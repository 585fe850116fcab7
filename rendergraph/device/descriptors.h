#pragma once
// The small objects every pass that binds resources creates the same way: set layouts, pipeline
// layouts, samplers, and one descriptor set per frame in flight.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/unique_handle.h"

namespace sg::vk {

UniqueDescriptorSetLayout create_set_layout(VkDevice device,
                                            std::span<const VkDescriptorSetLayoutBinding> bindings);

// One set layout and at most one push-constant range (size 0: none).
UniquePipelineLayout create_pipeline_layout(VkDevice device, VkDescriptorSetLayout set_layout,
                                            VkPushConstantRange push = {});

// One mip level. `compare` makes a depth-comparison sampler with VK_COMPARE_OP_LESS_OR_EQUAL
// (1 where the reference is not farther than the texel).
UniqueSampler create_sampler(VkDevice device, VkFilter filter, bool compare = false,
                             VkSamplerAddressMode address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);

// `count` sets of one layout in a pool of their own: a pass that rewrites its set every frame
// keeps one per frame slot, so the GPU never reads a set the CPU is updating.
struct DescriptorSets {
  UniqueDescriptorPool pool;
  std::vector<VkDescriptorSet> sets;
};
DescriptorSets allocate_sets(VkDevice device, VkDescriptorSetLayout layout,
                             std::span<const VkDescriptorSetLayoutBinding> bindings, uint32_t count);

}  // namespace sg::vk
