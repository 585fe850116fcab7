// SPDX-License-Identifier: MIT
#include "systems/frame/headless_frames.h"

#include <chrono>
#include <cstdio>

#include "rendergraph/device/frame_ring.h"
#include "systems/frame/frame.h"
#include "systems/frame/gpu_time_log.h"

namespace sg {
namespace {

double milliseconds(std::chrono::steady_clock::duration elapsed) {
  return std::chrono::duration<double, std::milli>(elapsed).count();
}

}  // namespace

void RunRecord::append(const RunRecord& later) {
  cpu_frame_ms.insert(cpu_frame_ms.end(), later.cpu_frame_ms.begin(), later.cpu_frame_ms.end());
  wall_frame_ms.insert(wall_frame_ms.end(), later.wall_frame_ms.begin(), later.wall_frame_ms.end());
}

RunRecord render_headless_frames(Frame& frame, vk::FrameRing& ring, uint32_t count, GpuTimeLog& gpu_times,
                                 bool progress, uint64_t first_frame, const std::atomic<bool>* stop) {
  constexpr double frame_seconds = 1.0 / 60.0;
  RunRecord record{{}, {}, &gpu_times};
  auto previous_start = std::chrono::steady_clock::now();
  const auto stopped = [stop] { return stop && stop->load(std::memory_order_relaxed); };
  uint32_t i = 0;
  for (; i < count && !stopped(); ++i) {
    const auto frame_start = std::chrono::steady_clock::now();  // before the waits
    if (i > 0) record.wall_frame_ms.push_back(milliseconds(frame_start - previous_start));
    previous_start = frame_start;
    vk::FrameSlot& slot = frame.begin(ring);
    const auto start = std::chrono::steady_clock::now();  // after the wait for the GPU
    frame.record(slot, double(first_frame + i) * frame_seconds);
    ring.submit();
    gpu_times.add(frame.executor().latest_timings());
    record.cpu_frame_ms.push_back(milliseconds(std::chrono::steady_clock::now() - start));
    if (progress && count >= 100 && (i + 1) % (count / 10) == 0) {
      std::printf("shadowgraph: %u/%u frames\n", i + 1, count);
    }
  }
  const uint32_t rendered = i;
  ring.wait_idle();
  if (rendered > 0)
    record.wall_frame_ms.push_back(milliseconds(std::chrono::steady_clock::now() - previous_start));
  // The last frames' timestamps are readable now that the GPU is idle, oldest first.
  const uint32_t in_flight = ring.frames_in_flight();
  for (uint32_t k = rendered > in_flight ? rendered - in_flight : 0; k < rendered; ++k) {
    frame.executor().collect_timings(k % in_flight);
    gpu_times.add(frame.executor().latest_timings());
  }
  return record;
}

}  // namespace sg
