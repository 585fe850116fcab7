// SPDX-License-Identifier: MIT
#pragma once
// The physical images and buffers behind one compiled plan's transients.
//
// The plan's own placement uses size estimates; here every transient is created first, the
// device's real memory requirements are read back, and rg::plan_aliasing() places them again
// into heaps (one GpuAllocator allocation each). Resources whose lifetimes do not overlap are
// bound to the same memory. Transients with different memoryTypeBits never share a heap.
//
// Contract: the object must outlive every command buffer that uses its resources; the executor
// keeps one set per frame in flight for that reason.
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/compiled_plan.h"
#include "rendergraph/device/gpu_allocator.h"
#include "rendergraph/device/image_views.h"

namespace sg::vk {

class VulkanContext;

class TransientResources {
 public:
  TransientResources(VulkanContext& context, const rg::CompiledPlan& plan);
  ~TransientResources();
  TransientResources(const TransientResources&) = delete;
  TransientResources& operator=(const TransientResources&) = delete;

  // Null handles for imported resources and for transients no executed pass touches.
  VkImage image(uint32_t resource) const { return objects_[resource].image; }
  VkBuffer buffer(uint32_t resource) const { return objects_[resource].buffer; }
  ImageViewCache* views(uint32_t resource) const { return objects_[resource].views.get(); }

  uint64_t heap_bytes() const { return heap_bytes_; }            // memory actually allocated
  uint64_t unaliased_bytes() const { return unaliased_bytes_; }  // had nothing been shared

 private:
  struct Object {
    VkImage image = VK_NULL_HANDLE;
    VkBuffer buffer = VK_NULL_HANDLE;
    std::unique_ptr<ImageViewCache> views;
  };

  void release();

  VulkanContext& context_;
  std::vector<Object> objects_;  // by graph resource index
  std::vector<Allocation> heaps_;
  uint64_t heap_bytes_ = 0;
  uint64_t unaliased_bytes_ = 0;
};

}  // namespace sg::vk
