// SPDX-License-Identifier: MIT
#include "rendergraph/vulkan/pass_timer.h"

#include <algorithm>

#include "rendergraph/device/context.h"
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

PassTimer::PassTimer(VulkanContext& context, uint32_t slots) : device_(context.device()), slots_(slots) {
  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(context.physical_device(), &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(context.physical_device(), &family_count, families.data());
  const uint32_t valid_bits = families[context.queue_family()].timestampValidBits;
  if (valid_bits == 0) return;
  valid_mask_ = valid_bits >= 64 ? ~uint64_t{0} : (uint64_t{1} << valid_bits) - 1;
  period_ns_ = context.properties().limits.timestampPeriod;
}

PassTimer::~PassTimer() {
  for (const Slot& slot : slots_) {
    if (slot.pool != VK_NULL_HANDLE) vkDestroyQueryPool(device_, slot.pool, nullptr);
  }
}

bool PassTimer::collect(uint32_t slot_index, std::vector<double>& pass_ms) {
  pass_ms.clear();
  if (!supported()) return false;
  Slot& slot = slots_[slot_index];
  bool read = false;
  if (slot.pass_count > 0) {
    ticks_.resize(2 * size_t{slot.pass_count});
    // The frame ring has waited for this slot's previous frame, so the results are available;
    // VK_NOT_READY would mean that frame was never submitted, and it is skipped.
    const VkResult result =
        vkGetQueryPoolResults(device_, slot.pool, 0, 2 * slot.pass_count, ticks_.size() * sizeof(uint64_t),
                              ticks_.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
    if (result == VK_SUCCESS) {
      for (uint32_t p = 0; p < slot.pass_count; ++p) {
        const uint64_t ticks = (ticks_[2 * p + 1] - ticks_[2 * p]) & valid_mask_;
        pass_ms.push_back(double(ticks) * period_ns_ * 1e-6);
      }
      read = true;
    } else if (result != VK_NOT_READY) {
      check(result, "vkGetQueryPoolResults");
    }
  }
  slot.pass_count = 0;
  return read;
}

void PassTimer::begin_frame(VkCommandBuffer cmd, uint32_t slot_index, uint32_t pass_count) {
  if (!supported()) return;
  Slot& slot = slots_[slot_index];
  if (pass_count > slot.capacity) {
    if (slot.pool != VK_NULL_HANDLE) vkDestroyQueryPool(device_, slot.pool, nullptr);
    slot.pool = VK_NULL_HANDLE;
    slot.capacity = std::max(pass_count, 2 * slot.capacity);
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * slot.capacity;
    check(vkCreateQueryPool(device_, &info, nullptr, &slot.pool), "vkCreateQueryPool");
  }
  slot.pass_count = pass_count;
  if (pass_count > 0) vkCmdResetQueryPool(cmd, slot.pool, 0, 2 * pass_count);
}

void PassTimer::begin_pass(VkCommandBuffer cmd, uint32_t slot, uint32_t pass) const {
  if (!supported()) return;
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, slots_[slot].pool, 2 * pass);
}

void PassTimer::end_pass(VkCommandBuffer cmd, uint32_t slot, uint32_t pass) const {
  if (!supported()) return;
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, slots_[slot].pool, 2 * pass + 1);
}

}  // namespace sg::vk
