// SPDX-License-Identifier: MIT
#pragma once
// Single synchronization2 barriers. The render graph computes
// and batches the frame's barriers itself; this is for the few transitions outside it
// (presentation blits, readbacks).
#include <vulkan/vulkan.h>

namespace sg::vk {

struct ImageTransition {
  VkImage image = VK_NULL_HANDLE;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImageLayout new_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags2 src_stages = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 src_access = VK_ACCESS_2_NONE;
  VkPipelineStageFlags2 dst_stages = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 dst_access = VK_ACCESS_2_NONE;
  uint32_t base_layer = 0;
  uint32_t layer_count = VK_REMAINING_ARRAY_LAYERS;
};

// Records the transition over all mips of the layers base_layer .. base_layer + layer_count.
void transition(VkCommandBuffer cmd, const ImageTransition& t);

// Records a global memory dependency (all resources), e.g. copies before host reads.
void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stages, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stages, VkAccessFlags2 dst_access);

}  // namespace sg::vk
