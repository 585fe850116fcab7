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

// The first frame's commands wait for an event that only nearly_ready sets, so the third frame,
// which reuses the first one's slot, can only begin if nearly_ready is called while it waits.
TEST_F(FrameRingTest, NearlyReadyIsCalledBeforeTheWaitEnds) {
  const VkDevice device = context.device();
  VkEventCreateInfo info{VK_STRUCTURE_TYPE_EVENT_CREATE_INFO};
  VkEvent event = VK_NULL_HANDLE;
  vk::check(vkCreateEvent(device, &info, nullptr, &event), "vkCreateEvent");
  std::atomic<bool> set_by_nearly_ready{false};
  std::atomic<bool> done{false};
  // Should nearly_ready not come, the event is set after a while so that the test fails instead
  // of hanging.
  std::thread watchdog([&] {
    for (int i = 0; i < 200 && !done; ++i) std::this_thread::sleep_for(50ms);
    if (!done) vkSetEvent(device, event);
  });
  {
    vk::FrameRing ring(context, 2);
    vk::FrameSlot& first = ring.begin_frame();
    vkCmdWaitEvents(first.cmd, 1, &event, VK_PIPELINE_STAGE_HOST_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                    nullptr, 0, nullptr, 0, nullptr);
    ring.submit();
    ring.begin_frame();
    ring.submit();
    ring.begin_frame(
        [&] {
          set_by_nearly_ready = vkGetEventStatus(device, event) == VK_EVENT_RESET;
          vkSetEvent(device, event);
        },
        100us);
    ring.submit();
  }  // the ring waits for its frames
  done = true;
  watchdog.join();
  vkDestroyEvent(device, event, nullptr);
  EXPECT_TRUE(set_by_nearly_ready) << "nearly_ready was not called before the wait for the GPU ended";
}

}  // namespace
}  // namespace sg::test
