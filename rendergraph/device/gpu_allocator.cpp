// SPDX-License-Identifier: MIT
#include "rendergraph/device/gpu_allocator.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

#include <sys/mman.h>
#include <unistd.h>

#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {
namespace {

struct MemoryPreference {
  VkMemoryPropertyFlags required;
  VkMemoryPropertyFlags preferred;
};

MemoryPreference preference_for(MemoryUsage usage) {
  constexpr VkMemoryPropertyFlags host =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  switch (usage) {
    case MemoryUsage::gpu_only: return {VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0};
    case MemoryUsage::upload: return {host, 0};
    case MemoryUsage::readback: return {host, VK_MEMORY_PROPERTY_HOST_CACHED_BIT};
    case MemoryUsage::stream: return {host, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT};
  }
  return {0, 0};
}

bool is_host_visible(MemoryUsage usage) { return usage != MemoryUsage::gpu_only; }

// On a CPU device the shaders read every image through this mapping, and a shadow atlas's rows
// lie 16 KiB apart: each row a kernel's taps reach is another 4 KiB page. Asked before anything
// touches the block, the kernel backs it with 2 MiB pages where transparent huge pages are left
// to madvise (Debian's default). Advice only: where the kernel declines, nothing changes.
// Lavapipe, `default` at 1280x720 on a 2-core EPYC VM, 2026-12-05: frames 126-132 ms against
// 130-148 without, five interleaved runs (docs/PERFORMANCE.md).
void advise_huge_pages(void* mapped, VkDeviceSize size) {
#ifdef MADV_HUGEPAGE
  const auto page = static_cast<uintptr_t>(sysconf(_SC_PAGESIZE));  // 16 or 64 KiB on some ARM kernels
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(mapped) + page - 1) & ~(page - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(mapped) + size) & ~(page - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)mapped, (void)size;
#endif
}

}  // namespace

uint32_t choose_memory_type(const VkPhysicalDeviceMemoryProperties& properties, uint32_t type_bits,
                            MemoryUsage usage) {
  const MemoryPreference pref = preference_for(usage);
  uint32_t fallback = UINT32_MAX;
  for (uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
    const VkMemoryPropertyFlags flags = properties.memoryTypes[i].propertyFlags;
    if (!(type_bits & (1u << i)) || (flags & pref.required) != pref.required) continue;
    if ((flags & pref.preferred) == pref.preferred) return i;
    if (fallback == UINT32_MAX) fallback = i;
  }
  if (fallback == UINT32_MAX && usage == MemoryUsage::gpu_only) {
    return choose_memory_type(properties, type_bits, MemoryUsage::upload);
  }
  return fallback;
}

GpuAllocator::GpuAllocator(VkPhysicalDevice physical_device, VkDevice device, VkDeviceSize block_size)
    : device_(device), block_size_(block_size) {
  vkGetPhysicalDeviceMemoryProperties(physical_device, &memory_properties_);
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(physical_device, &properties);
  host_memory_ = properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
}

GpuAllocator::~GpuAllocator() {
  for (const Block& block : blocks_) {
    if (block.memory != VK_NULL_HANDLE) vkFreeMemory(device_, block.memory, nullptr);
  }
}

uint32_t GpuAllocator::create_block(uint32_t memory_type, ResourceTiling tiling, VkDeviceSize size) {
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = size;
  info.memoryTypeIndex = memory_type;
  Block block;
  check(vkAllocateMemory(device_, &info, nullptr, &block.memory),
        "vkAllocateMemory of a " + std::to_string(size >> 20) + " MiB block");
  const VkMemoryPropertyFlags flags = memory_properties_.memoryTypes[memory_type].propertyFlags;
  if (flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
    check(vkMapMemory(device_, block.memory, 0, VK_WHOLE_SIZE, 0, &block.mapped), "vkMapMemory");
    if (host_memory_) advise_huge_pages(block.mapped, size);
  }
  block.memory_type = memory_type;
  block.tiling = tiling;
  block.ranges = RangeAllocator(size);
  for (uint32_t i = 0; i < blocks_.size(); ++i) {
    if (blocks_[i].memory == VK_NULL_HANDLE) {
      blocks_[i] = std::move(block);
      return i;
    }
  }
  blocks_.push_back(std::move(block));
  return static_cast<uint32_t>(blocks_.size() - 1);
}

Allocation GpuAllocator::allocate(const VkMemoryRequirements& requirements, MemoryUsage usage,
                                  ResourceTiling tiling) {
  const uint32_t type = choose_memory_type(
      memory_properties_, requirements.memoryTypeBits,
      usage == MemoryUsage::stream && stream_in_host_memory_ ? MemoryUsage::upload : usage);
  if (type == UINT32_MAX) {
    throw VulkanError("no Vulkan memory type is both allowed for the resource (memory type bits " +
                      std::to_string(requirements.memoryTypeBits) +
                      ") and host-visible/coherent as required");
  }
  const bool host = is_host_visible(usage);
  auto place = [&](uint32_t index) -> std::optional<Allocation> {
    Block& block = blocks_[index];
    if (block.memory == VK_NULL_HANDLE || block.memory_type != type || block.tiling != tiling ||
        (host && !block.mapped)) {
      return std::nullopt;
    }
    const auto offset = block.ranges.allocate(requirements.size, requirements.alignment);
    if (!offset) return std::nullopt;
    ++block.allocation_count;
    Allocation a;
    a.memory = block.memory;
    a.offset = *offset;
    a.size = requirements.size;
    a.block = index;
    if (block.mapped) a.mapped = static_cast<std::byte*>(block.mapped) + *offset;
    return a;
  };
  for (uint32_t i = 0; i < blocks_.size(); ++i) {
    if (auto a = place(i)) return *a;
  }
  // Resources larger than a block get a block of their own size.
  const VkDeviceSize size = std::max(block_size_, requirements.size);
  // The device-local memory a CPU can map may be a window (256 MiB without resizable BAR) that
  // other processes share: where it runs out, streamed data takes host memory, as upload's.
  if (usage != MemoryUsage::stream || stream_in_host_memory_ ||
      type == choose_memory_type(memory_properties_, requirements.memoryTypeBits, MemoryUsage::upload)) {
    return *place(create_block(type, tiling, size));
  }
  try {
    return *place(create_block(type, tiling, size));
  } catch (const VulkanError& error) {
    stream_in_host_memory_ = true;
    std::printf("shadowgraph: %s; per-frame data the GPU reads now lies in host memory, read over the bus\n",
                error.what());
    return allocate(requirements, usage, tiling);
  }
}

void GpuAllocator::free(const Allocation& allocation) {
  if (allocation.block == UINT32_MAX) return;
  Block& block = blocks_[allocation.block];
  block.ranges.free(allocation.offset, allocation.size);
  --block.allocation_count;
  if (block.allocation_count == 0) {
    // Give empty blocks back at once: level loads and resizes are rare, and holding memory
    // the user's budget says is free would be worse than re-allocating a block later.
    vkFreeMemory(device_, block.memory, nullptr);
    block = Block{};
  }
}

MemoryStats GpuAllocator::stats() const {
  MemoryStats s;
  for (const Block& block : blocks_) {
    if (block.memory == VK_NULL_HANDLE) continue;
    s.reserved_bytes += block.ranges.capacity();
    s.used_bytes += block.ranges.used();
    s.block_count += 1;
    s.allocation_count += block.allocation_count;
  }
  return s;
}

}  // namespace sg::vk
