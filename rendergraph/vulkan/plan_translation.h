// SPDX-License-Identifier: MIT
#pragma once
// The compiled plan's vocabulary in Vulkan terms. The core's enums carry Vulkan's numeric values
// (rendergraph/core/sync_types.h), so each conversion is a cast; plan_translation.cpp
// static_asserts every enumerator against the Vulkan constant it claims to be.
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/compiled_plan.h"

namespace sg::vk {

class Image;
class ImageViewCache;

VkPipelineStageFlags2 to_vk(rg::PipelineStage stages);
VkAccessFlags2 to_vk(rg::Access access);
VkImageLayout to_vk(rg::ImageLayout layout);
VkFormat to_vk(rg::Format format);
// Throws std::invalid_argument for a format the graph cannot describe.
rg::Format from_vk(VkFormat format);
VkImageUsageFlags to_vk(rg::ImageUsage usage);
VkBufferUsageFlags to_vk(rg::BufferUsage usage);
// How the graph describes `image` (size, format, layers, mips, cube compatibility).
rg::ImageDesc graph_desc(const Image& image);
// `range` must be resolved (no rg::remaining).
VkImageSubresourceRange to_vk(const rg::SubresourceRange& range, VkImageAspectFlags aspect);

// The Vulkan object behind one graph resource in one frame: a transient the executor created or
// an imported one the caller bound. `views` is null for images nobody can make views of
// (swapchain images, which the sandbox only blits to).
struct PhysicalResource {
  VkImage image = VK_NULL_HANDLE;
  VkBuffer buffer = VK_NULL_HANDLE;
  ImageViewCache* views = nullptr;
  VkImageAspectFlags aspect = 0;
};

// Records `batch` as one vkCmdPipelineBarrier2 (nothing when it is empty). `resources` is
// indexed by graph resource index. The vectors are scratch space reused across calls so that
// recording allocates nothing once they have grown.
struct BarrierScratch {
  std::vector<VkImageMemoryBarrier2> images;
  std::vector<VkBufferMemoryBarrier2> buffers;
};
void record_barriers(VkCommandBuffer cmd, const rg::BarrierBatch& batch,
                     std::span<const PhysicalResource> resources, BarrierScratch& scratch);

}  // namespace sg::vk
