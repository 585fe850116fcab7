// SPDX-License-Identifier: MIT
#pragma once
// GPU timestamps around every pass of a frame, one query pool per frame in flight. A slot's
// results are read when the slot is used again, after the frame ring has waited for it, so
// reading never stalls the CPU.
//
// On NVIDIA each timestamp waits for the work before it, top- or bottom-of-pipe alike, and yet
// costs little: an H100 frame of 100,000 lights took 10.56-10.58 ms with only the frame's first
// and last pass timed against 10.62-10.63 with every pass, 22.57 against 22.61-22.64 at eye height
// (2026-12-06, docs/PERFORMANCE.md). The shadow time budget and the automatic choice of shadow
// raster (systems/shadows/raster_choice.h) learn from the passes' times: left without them, a
// frame of 1,024 lights at eye height took 54.5-55.0 ms where it takes 12.2.
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
