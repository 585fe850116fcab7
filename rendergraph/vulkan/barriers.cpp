#include "rendergraph/vulkan/barriers.h"

namespace sg::vk {

void transition(VkCommandBuffer cmd, const ImageTransition& t) {
  VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  barrier.srcStageMask = t.src_stages;
  barrier.srcAccessMask = t.src_access;
  barrier.dstStageMask = t.dst_stages;
  barrier.dstAccessMask = t.dst_access;
  barrier.oldLayout = t.old_layout;
  barrier.newLayout = t.new_layout;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = t.image;
  barrier.subresourceRange = {t.aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace sg::vk
