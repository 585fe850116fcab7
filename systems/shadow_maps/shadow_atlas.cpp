// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/shadow_atlas.h"

#include <algorithm>

#include "rendergraph/device/context.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/gpu/gpu_textures.h"

namespace sg {

shadows::DeviceShadowLimits shadow_limits(const vk::VulkanContext& context) {
  const VkPhysicalDeviceLimits& limits = context.properties().limits;
  VkPhysicalDeviceMaintenance3Properties maintenance3{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &maintenance3};
  vkGetPhysicalDeviceProperties2(context.physical_device(), &properties);
  VkPhysicalDeviceMemoryProperties memory;
  vkGetPhysicalDeviceMemoryProperties(context.physical_device(), &memory);
  uint64_t heap = 0;
  for (uint32_t h = 0; h < memory.memoryHeapCount; ++h) {
    if (memory.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
      heap = std::max(heap, memory.memoryHeaps[h].size);
  }
  return {limits.maxImageDimension2D, limits.maxImageArrayLayers, maintenance3.maxMemoryAllocationSize, heap,
          limits.maxStorageBufferRange};
}

vk::GraphicsPipelineDesc shadow_pipeline_desc(VkPipelineLayout layout) {
  vk::GraphicsPipelineDesc desc;
  scene_vertex_input(desc, VertexInput::position);
  desc.depth_format = vk::to_vk(ShadowAtlas::depth_format);
  // Receivers apply each light's own bias (docs/ALGORITHMS.md section 4.6), so casters are drawn as
  // they are, both faces: thin and open meshes cast too.
  desc.cull_mode = VK_CULL_MODE_NONE;
  desc.layout = layout;
  return desc;
}

vk::GraphicsPipelineDesc shadow_cut_out_pipeline_desc(VkPipelineLayout layout, const GpuTextures& textures) {
  vk::GraphicsPipelineDesc desc = shadow_pipeline_desc(layout);
  scene_vertex_input(desc, VertexInput::position_uv);
  desc.fragment_specialization = material_pass_constants(0, 0, textures);
  return desc;
}

ShadowAtlas::ShadowAtlas(vk::VulkanContext& context, uint64_t budget_bytes, bool static_layers)
    : context_(context), keeps_static_layers_(static_layers) {
  const shadows::DeviceShadowLimits limits = shadow_limits(context);
  shape_ = shadows::atlas_shape(budget_bytes > 0 ? budget_bytes : shadows::default_shadow_budget(limits),
                                limits, static_layers);
  fit(1);
}

bool ShadowAtlas::fit(uint32_t pages) {
  const uint32_t wanted =
      shadows::atlas_pages_to_create(pages_, std::min(pages, shape_.max_pages), shape_.max_pages);
  if (wanted == pages_) return false;
  if (image_.handle() != VK_NULL_HANDLE) vkDeviceWaitIdle(context_.device());
  // Transfer destination: the compute raster copies its depths in (ShadowViewBatch).
  constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  image_ = vk::Image(context_, {{shape_.page_size, shape_.page_size},
                                vk::to_vk(depth_format),
                                usage,
                                1,
                                wanted,
                                VK_IMAGE_VIEW_TYPE_2D_ARRAY,
                                "shadow atlas"});
  pages_ = wanted;
  if (keeps_static_layers_) {
    static_layers_ = vk::Buffer(
        context_, {uint64_t{shape_.page_size} * shape_.page_size * pages_ * sizeof(float),
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::gpu_only, "shadow static layers"});
  }
  return true;
}

uint32_t ShadowAtlas::texel_bytes() const { return shadows::atlas_texel_cost(keeps_static_layers_); }

uint64_t ShadowAtlas::bytes() const {
  return uint64_t{shape_.page_size} * shape_.page_size * pages_ * texel_bytes();
}

}  // namespace sg
