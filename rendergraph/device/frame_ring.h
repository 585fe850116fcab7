// SPDX-License-Identifier: MIT
#pragma once
// Per-frame command recording with a fixed number of frames in flight: the CPU records
// frame N+1 while the GPU still runs frame N, and waits only when it would overwrite the
// command buffer of a frame the GPU has not finished.
#include <chrono>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/unique_handle.h"

namespace sg::vk {

class VulkanContext;

struct FrameSlot {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkSemaphore image_acquired = VK_NULL_HANDLE;  // for swapchain acquisition into this frame
  uint64_t frame_number = 0;
  uint32_t slot = 0;  // which of the frames in flight: per-slot resources are indexed by it
};

struct SemaphoreWait {
  VkSemaphore semaphore;
  VkPipelineStageFlags2 stages;
  uint64_t value = 0;  // a timeline semaphore's value to wait for; binary semaphores ignore it
};

class FrameRing {
 public:
  explicit FrameRing(VulkanContext& context, uint32_t frames_in_flight = 2);
  ~FrameRing();
  FrameRing(const FrameRing&) = delete;
  FrameRing& operator=(const FrameRing&) = delete;

  // Waits until the slot's previous use finished on the GPU, then begins its command buffer.
  // A frame begun and never submitted is simply dropped by the next begin_frame.
  FrameSlot& begin_frame();
  // The same, calling `nearly_ready` once before it returns: `lead` before the wait is expected
  // to end (the last wait's length foretells this one's), or when the wait ends if that is
  // sooner. For what takes a while to get going once a frame starts, such as threads that fell
  // asleep during the wait: woken here, their wake-up overlaps the GPU's work instead of the
  // frame's.
  FrameSlot& begin_frame(const std::function<void()>& nearly_ready, std::chrono::microseconds lead);
  // Ends and submits the current frame's commands.
  void submit(std::span<const SemaphoreWait> waits = {}, std::span<const VkSemaphore> signals = {});
  // Waits for every submitted frame.
  void wait_idle();

  uint32_t frames_in_flight() const { return static_cast<uint32_t>(slots_.size()); }

 private:
  struct Slot {
    UniqueCommandPool pool;
    FrameSlot frame;
    UniqueFence done;
    UniqueSemaphore image_acquired;
  };
  VulkanContext& context_;
  std::vector<Slot> slots_;
  uint64_t frame_number_ = 0;
  std::chrono::steady_clock::duration last_wait_{};  // begin_frame's last wait for its slot
  Slot* current_ = nullptr;
  // Reused by submit() so a frame allocates nothing.
  std::vector<VkSemaphoreSubmitInfo> wait_infos_;
  std::vector<VkSemaphoreSubmitInfo> signal_infos_;
};

}  // namespace sg::vk
