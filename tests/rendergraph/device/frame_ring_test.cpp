// SPDX-License-Identifier: MIT
// FrameRing's early call: begin_frame(nearly_ready, lead) calls nearly_ready once per frame, and
// during the wait for the GPU, not after it.
#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/vulkan_error.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

using namespace std::chrono_literals;

class FrameRingTest : public GpuTest {};

TEST_F(FrameRingTest, NearlyReadyIsCalledOncePerFrame) {
  vk::FrameRing ring(context, 2);
  int calls = 0;
  for (int frame = 0; frame < 6; ++frame) {
    ring.begin_frame([&] { ++calls; }, 100us);
    EXPECT_EQ(calls, frame + 1);
    ring.submit();
  }
  ring.begin_frame();  // the plain wait calls nothing
  EXPECT_EQ(calls, 6);
}

// The first frame waits for a timeline value that only nearly_ready signals, so the third frame,
// which reuses the first one's slot, can only begin if nearly_ready is called while it waits. (A
// host-set event that a submitted frame waits on is invalid: VUID-vkSetEvent-event-09543.)
TEST_F(FrameRingTest, NearlyReadyIsCalledBeforeTheWaitEnds) {
  const VkDevice device = context.device();
  VkSemaphoreTypeCreateInfo timeline{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
  timeline.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO, &timeline};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  vk::check(vkCreateSemaphore(device, &info, nullptr, &semaphore), "vkCreateSemaphore");
  // Signals the timeline's value 1 unless already done (a timeline's value only rises); true for
  // the call that did.
  std::atomic<bool> signaled{false};
  const auto signal_once = [&] {
    if (signaled.exchange(true)) return false;
    VkSemaphoreSignalInfo signal_info{VK_STRUCTURE_TYPE_SEMAPHORE_SIGNAL_INFO};
    signal_info.semaphore = semaphore;
    signal_info.value = 1;
    vkSignalSemaphore(device, &signal_info);
    return true;
  };
  std::atomic<bool> signaled_by_nearly_ready{false};
  // Should nearly_ready not come, the value is signaled after a while so that the test fails
  // instead of hanging.
  std::atomic<bool> done{false};
  std::thread watchdog([&] {
    for (int i = 0; i < 200 && !done; ++i) std::this_thread::sleep_for(50ms);
    signal_once();
  });
  {
    vk::FrameRing ring(context, 2);
    ring.begin_frame();
    const vk::SemaphoreWait wait{semaphore, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 1};
    ring.submit({&wait, 1});
    ring.begin_frame();
    ring.submit();
    ring.begin_frame([&] { signaled_by_nearly_ready = signal_once(); }, 100us);
    ring.submit();
  }  // the ring waits for its frames
  done = true;
  watchdog.join();
  vkDestroySemaphore(device, semaphore, nullptr);
  EXPECT_TRUE(signaled_by_nearly_ready) << "nearly_ready was not called before the wait for the GPU ended";
}

}  // namespace
}  // namespace sg::test
