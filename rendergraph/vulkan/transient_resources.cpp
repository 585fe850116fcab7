// SPDX-License-Identifier: MIT
#include "rendergraph/vulkan/transient_resources.h"

#include <algorithm>
#include <map>
#include <span>
#include <utility>

#include "rendergraph/core/aliasing.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/device/vulkan_error.h"
#include "rendergraph/vulkan/plan_translation.h"

namespace sg::vk {
namespace {

VkImage create_image(VkDevice device, const rg::CompiledResource& resource) {
  const rg::ImageDesc& desc = resource.image;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.flags = desc.cube_compatible ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = to_vk(desc.format);
  info.extent = {desc.width, desc.height, 1};
  info.mipLevels = desc.mips;
  info.arrayLayers = desc.layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = to_vk(resource.image_usage);
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  check(vkCreateImage(device, &info, nullptr, &image), "vkCreateImage " + resource.name);
  return image;
}

VkBuffer create_buffer(VkDevice device, const rg::CompiledResource& resource) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = resource.buffer.size;
  info.usage = to_vk(resource.buffer_usage);
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  check(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer " + resource.name);
  return buffer;
}

// Whether every transient of a group, placed by `aliasing` (the device's sizes), takes over memory
// only from transients the compiled plan named as its previous occupants: its barriers
// (rendergraph/core/barriers.cpp) wait for those last uses and no others. The device's sizes can
// pack a group otherwise than compile()'s estimates did.
bool waits_for_its_previous_occupants(const rg::AliasingPlan& aliasing, std::span<const uint32_t> resources,
                                      const rg::CompiledPlan& plan) {
  for (size_t r = 0; r < resources.size(); ++r) {
    const std::vector<uint32_t>& planned = plan.resources[resources[r]].placement->previous_occupants;
    for (const uint32_t previous : aliasing.placements[r].previous_occupants) {
      if (std::find(planned.begin(), planned.end(), resources[previous]) == planned.end()) return false;
    }
  }
  return true;
}

// Each request in memory of its own.
rg::AliasingPlan unaliased(std::span<const rg::AliasingRequest> requests) {
  rg::AliasingPlan plan;
  for (uint32_t r = 0; r < requests.size(); ++r) {
    plan.heaps.push_back({requests[r].kind, requests[r].size, requests[r].alignment});
    plan.placements.push_back({r, 0, requests[r].size, {}});
  }
  return plan;
}

}  // namespace

TransientResources::TransientResources(VulkanContext& context, const rg::CompiledPlan& plan)
    : context_(context), objects_(plan.resources.size()) {
  const VkDevice device = context.device();
  // Transients that may share memory: same kind, same allowed memory types.
  struct Group {
    std::vector<uint32_t> resources;
    std::vector<rg::AliasingRequest> requests;
  };
  std::map<std::pair<rg::ResourceKind, uint32_t>, Group> groups;
  try {
    for (uint32_t i = 0; i < plan.resources.size(); ++i) {
      const rg::CompiledResource& resource = plan.resources[i];
      if (resource.imported || !resource.lifetime) continue;
      VkMemoryRequirements requirements;
      if (resource.kind == rg::ResourceKind::image) {
        objects_[i].image = create_image(device, resource);
        vkGetImageMemoryRequirements(device, objects_[i].image, &requirements);
        context.set_name(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(objects_[i].image),
                         resource.name.c_str());
      } else {
        objects_[i].buffer = create_buffer(device, resource);
        vkGetBufferMemoryRequirements(device, objects_[i].buffer, &requirements);
        context.set_name(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(objects_[i].buffer),
                         resource.name.c_str());
      }
      Group& group = groups[{resource.kind, requirements.memoryTypeBits}];
      group.resources.push_back(i);
      group.requests.push_back(
          {resource.kind, requirements.size, requirements.alignment, *resource.lifetime});
      unaliased_bytes_ += requirements.size;
    }

    for (const auto& [key, group] : groups) {
      const auto [kind, memory_types] = key;
      rg::AliasingPlan aliasing = rg::plan_aliasing(group.requests);
      if (!waits_for_its_previous_occupants(aliasing, group.resources, plan))
        aliasing = unaliased(group.requests);
      const size_t first_heap = heaps_.size();
      for (const rg::MemoryHeap& heap : aliasing.heaps) {
        const VkMemoryRequirements requirements{heap.size, heap.alignment, memory_types};
        heaps_.push_back(context.allocator().allocate(
            requirements, MemoryUsage::gpu_only,
            kind == rg::ResourceKind::image ? ResourceTiling::optimal : ResourceTiling::linear));
        heap_bytes_ += heap.size;
      }
      for (size_t r = 0; r < group.resources.size(); ++r) {
        const uint32_t index = group.resources[r];
        const rg::MemoryPlacement& placement = aliasing.placements[r];
        const Allocation& heap = heaps_[first_heap + placement.heap];
        Object& object = objects_[index];
        if (kind == rg::ResourceKind::image) {
          check(vkBindImageMemory(device, object.image, heap.memory, heap.offset + placement.offset),
                "vkBindImageMemory " + plan.resources[index].name);
          object.views = std::make_unique<ImageViewCache>(device, object.image,
                                                          to_vk(plan.resources[index].image.format));
        } else {
          check(vkBindBufferMemory(device, object.buffer, heap.memory, heap.offset + placement.offset),
                "vkBindBufferMemory " + plan.resources[index].name);
        }
      }
    }
  } catch (...) {
    release();
    throw;
  }
}

TransientResources::~TransientResources() { release(); }

void TransientResources::release() {
  const VkDevice device = context_.device();
  for (Object& object : objects_) {
    object.views.reset();
    if (object.image != VK_NULL_HANDLE) vkDestroyImage(device, object.image, nullptr);
    if (object.buffer != VK_NULL_HANDLE) vkDestroyBuffer(device, object.buffer, nullptr);
    object = {};
  }
  for (const Allocation& heap : heaps_) context_.allocator().free(heap);
  heaps_.clear();
}

}  // namespace sg::vk
