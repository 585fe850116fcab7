// SPDX-License-Identifier: MIT
#pragma once
// The offscreen frame loop shared by the headless sandbox and the tools that measure the frame.
#include <atomic>
#include <cstdint>
#include <vector>

#include "rendergraph/device/fwd.h"

namespace sg {

class Frame;
class GpuTimeLog;

// What a run measured, for the summary and --stats.
struct RunRecord {
  // Per rendered frame: CPU time to update, build, compile, record and submit it, not counting
  // waits for the GPU (the frame ring's fence, the swapchain's acquire and present).
  std::vector<double> cpu_frame_ms;
  // Elapsed time per frame, waits included: present to present in a window (after the first
  // frame), frame start to frame start headless (the last frame: to the GPU going idle).
  std::vector<double> wall_frame_ms;
  const GpuTimeLog* gpu_times = nullptr;

  // Appends `later`'s frames (a run rendered in several calls).
  void append(const RunRecord& later);
};

// Renders `count` frames, animation advancing a fixed 1/60 s per frame so runs repeat exactly,
// then waits for the GPU and collects the last frames' timings too. CPU times go into the
// returned record, GPU times into `gpu_times`. With `progress`, long runs print every tenth.
// `first_frame` numbers the first of them (its time is first_frame / 60 s), for runs rendered in
// several calls. Once `stop` is set (a signal handler's flag) no further frame starts: the record
// then holds fewer than `count`.
RunRecord render_headless_frames(Frame& frame, vk::FrameRing& ring, uint32_t count, GpuTimeLog& gpu_times,
                                 bool progress = false, uint64_t first_frame = 0,
                                 const std::atomic<bool>* stop = nullptr);

}  // namespace sg
