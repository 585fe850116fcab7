// SPDX-License-Identifier: MIT
#pragma once
// GPU timestamps around every pass of a frame, one query pool per frame in flight. A slot's
// results are read when the slot is used again, after the frame ring has waited for it, so
// reading never stalls the CPU.
//
// Devices whose graphics queue has no timestamps (timestampValidBits == 0) get no timings;
// supported() says so and the executor reports none.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/unique_handle.h"

namespace sg::vk {

class VulkanContext;

class PassTimer {
 public:
  PassTimer(VulkanContext& context, uint32_t slots);
  ~PassTimer();
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

  bool supported() const { return period_ns_ > 0.0; }

  // Reads the milliseconds of the slot's previous frame into `pass_ms` (one per pass) and
  // returns whether there were any; each frame's results are read once. The GPU must have
  // finished that frame.
  bool collect(uint32_t slot, std::vector<double>& pass_ms);
  // Prepares the slot for a frame of `pass_count` passes (collect first: this discards the
  // previous results) and records the pool reset into `cmd`.
  void begin_frame(VkCommandBuffer cmd, uint32_t slot, uint32_t pass_count);
  void begin_pass(VkCommandBuffer cmd, uint32_t slot, uint32_t pass) const;
  void end_pass(VkCommandBuffer cmd, uint32_t slot, uint32_t pass) const;

 private:
  struct Slot {
    VkQueryPool pool = VK_NULL_HANDLE;
    uint32_t capacity = 0;    // passes the pool has room for
    uint32_t pass_count = 0;  // passes of the frame last recorded in this slot
  };

  VkDevice device_;
  double period_ns_ = 0.0;
  uint64_t valid_mask_ = 0;
  std::vector<Slot> slots_;
  std::vector<uint64_t> ticks_;  // scratch for query results
};

}  // namespace sg::vk
