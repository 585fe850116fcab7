// SPDX-License-Identifier: MIT
#pragma once
// Device memory suballocator: resources take ranges of large VkDeviceMemory blocks instead of
// one vkAllocateMemory each (drivers cap the number of allocations, e.g. 4096, and each one is
// slow). Linear resources (buffers) and optimal-tiling images live in separate blocks, so
// bufferImageGranularity never needs padding. Host-visible blocks stay persistently mapped; on
// CPU devices each asks for 2 MiB pages as it is mapped.
// Not thread-safe: the engine allocates from one thread.
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/range_allocator.h"

namespace sg::vk {

enum class MemoryUsage {
  gpu_only,  // device-local, never mapped
  upload,    // host-visible and coherent, written by the CPU (staging, per-frame constants)
  readback,  // host-visible and coherent, preferably cached, read by the CPU
  // Host-visible and coherent, written by the CPU every frame and read by the GPU's passes (light
  // records, instances, shadow views): device-local where the device maps such memory (resizable
  // BAR), so that the passes read it from the card's memory rather than over the bus; host memory
  // where it has none or none is left. The CPU must only write it.
  stream,
};

// The memory type for a resource allowed `type_bits` (VkMemoryRequirements::memoryTypeBits) used
// as `usage`, among `properties`' types; UINT32_MAX where none is allowed and host-visible as
// `usage` requires. A gpu_only resource takes a host-visible type where the device has no
// device-local one for it (CPU drivers, some integrated GPUs).
uint32_t choose_memory_type(const VkPhysicalDeviceMemoryProperties& properties, uint32_t type_bits,
                            MemoryUsage usage);

enum class ResourceTiling { linear, optimal };

struct Allocation {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize size = 0;
  void* mapped = nullptr;  // at `offset`, for host-visible usages
  uint32_t block = UINT32_MAX;
};

struct MemoryStats {
  VkDeviceSize reserved_bytes = 0;  // in all blocks
  VkDeviceSize used_bytes = 0;      // handed out to resources
  uint32_t block_count = 0;
  uint32_t allocation_count = 0;
};

class GpuAllocator {
 public:
  static constexpr VkDeviceSize default_block_size = VkDeviceSize{64} << 20;

  GpuAllocator(VkPhysicalDevice physical_device, VkDevice device,
               VkDeviceSize block_size = default_block_size);
  ~GpuAllocator();
  GpuAllocator(const GpuAllocator&) = delete;
  GpuAllocator& operator=(const GpuAllocator&) = delete;

  // Throws VulkanError when no memory type fits or the device is out of memory.
  Allocation allocate(const VkMemoryRequirements& requirements, MemoryUsage usage, ResourceTiling tiling);
  void free(const Allocation& allocation);

  MemoryStats stats() const;

 private:
  struct Block {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    uint32_t memory_type = 0;
    ResourceTiling tiling = ResourceTiling::linear;
    RangeAllocator ranges{0};
    uint32_t allocation_count = 0;
  };

  uint32_t create_block(uint32_t memory_type, ResourceTiling tiling, VkDeviceSize size);

  VkDevice device_;
  VkDeviceSize block_size_;
  bool host_memory_ = false;            // a CPU device: blocks are the process's own pages
  bool stream_in_host_memory_ = false;  // the device-local memory it maps ran out: stream takes upload's
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  std::vector<Block> blocks_;  // a freed block keeps its slot (memory null) so indices stay valid
};

}  // namespace sg::vk
