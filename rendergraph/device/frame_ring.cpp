// SPDX-License-Identifier: MIT
#include "rendergraph/device/frame_ring.h"

#include <algorithm>

#include "rendergraph/device/context.h"
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

FrameRing::FrameRing(VulkanContext& context, uint32_t frames_in_flight) : context_(context) {
  const VkDevice device = context.device();
  slots_.resize(frames_in_flight);
  for (Slot& slot : slots_) {
    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool_info.queueFamilyIndex = context.queue_family();
    VkCommandPool pool;
    check(vkCreateCommandPool(device, &pool_info, nullptr, &pool), "vkCreateCommandPool");
    slot.pool = UniqueCommandPool(device, pool);

    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device, &alloc, &slot.frame.cmd), "vkAllocateCommandBuffers");

    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence_info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VkFence fence;
    check(vkCreateFence(device, &fence_info, nullptr, &fence), "vkCreateFence");
    slot.done = UniqueFence(device, fence);

    VkSemaphoreCreateInfo sem_info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore;
    check(vkCreateSemaphore(device, &sem_info, nullptr, &semaphore), "vkCreateSemaphore");
    slot.image_acquired = UniqueSemaphore(device, semaphore);
    slot.frame.image_acquired = semaphore;
  }
}

FrameRing::~FrameRing() { wait_idle(); }

FrameSlot& FrameRing::begin_frame() { return begin_frame(nullptr, {}); }

FrameSlot& FrameRing::begin_frame(const std::function<void()>& nearly_ready, std::chrono::microseconds lead) {
  Slot& slot = slots_[frame_number_ % slots_.size()];
  const VkFence fence = slot.done.get();
  const auto start = std::chrono::steady_clock::now();
  if (nearly_ready) {
    const auto until_nearly_ready = std::max(last_wait_ - lead, std::chrono::steady_clock::duration::zero());
    const VkResult early = vkWaitForFences(
        context_.device(), 1, &fence, VK_TRUE,
        static_cast<uint64_t>(
            std::chrono::duration_cast<std::chrono::nanoseconds>(until_nearly_ready).count()));
    if (early != VK_TIMEOUT) check(early, "vkWaitForFences");
    nearly_ready();
  }
  check(vkWaitForFences(context_.device(), 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  last_wait_ = std::chrono::steady_clock::now() - start;
  // The fence is reset at submit, so a frame abandoned before submission (an out-of-date
  // swapchain) leaves the slot reusable instead of waiting forever on an unsignalled fence.
  check(vkResetCommandPool(context_.device(), slot.pool.get(), 0), "vkResetCommandPool");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(slot.frame.cmd, &begin), "vkBeginCommandBuffer");
  slot.frame.slot = static_cast<uint32_t>(frame_number_ % slots_.size());
  slot.frame.frame_number = frame_number_++;
  current_ = &slot;
  return slot.frame;
}

void FrameRing::submit(std::span<const SemaphoreWait> waits, std::span<const VkSemaphore> signals) {
  Slot& slot = *current_;
  check(vkEndCommandBuffer(slot.frame.cmd), "vkEndCommandBuffer");
  auto semaphore_info = [](VkSemaphore semaphore, VkPipelineStageFlags2 stages, uint64_t value = 0) {
    VkSemaphoreSubmitInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    info.semaphore = semaphore;
    info.stageMask = stages;
    info.value = value;
    return info;
  };
  wait_infos_.clear();
  for (const SemaphoreWait& w : waits) wait_infos_.push_back(semaphore_info(w.semaphore, w.stages, w.value));
  signal_infos_.clear();
  for (VkSemaphore s : signals) {
    signal_infos_.push_back(semaphore_info(s, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT));
  }
  VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmd_info.commandBuffer = slot.frame.cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = static_cast<uint32_t>(wait_infos_.size());
  submit.pWaitSemaphoreInfos = wait_infos_.data();
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmd_info;
  submit.signalSemaphoreInfoCount = static_cast<uint32_t>(signal_infos_.size());
  submit.pSignalSemaphoreInfos = signal_infos_.data();
  const VkFence fence = slot.done.get();
  check(vkResetFences(context_.device(), 1, &fence), "vkResetFences");
  check(vkQueueSubmit2(context_.queue(), 1, &submit, fence), "vkQueueSubmit2");
  current_ = nullptr;
}

void FrameRing::wait_idle() {
  std::vector<VkFence> fences;
  for (const Slot& slot : slots_) fences.push_back(slot.done.get());
  if (!fences.empty()) {
    vkWaitForFences(context_.device(), static_cast<uint32_t>(fences.size()), fences.data(), VK_TRUE,
                    UINT64_MAX);
  }
}

}  // namespace sg::vk
