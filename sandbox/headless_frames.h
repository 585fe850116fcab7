#pragma once
// The offscreen frame loop shared by the headless sandbox and the tools that measure its frame.
#include <cstdint>

#include "rendergraph/device/fwd.h"
#include "sandbox/run.h"

namespace sg::sandbox {

class GpuTimeLog;
class SandboxFrame;

// Renders `count` frames, animation advancing a fixed 1/60 s per frame so runs repeat exactly,
// then waits for the GPU and collects the last frames' timings too. CPU times go into the
// returned record, GPU times into `gpu_times`. With `progress`, long runs print every tenth.
// `first_frame` numbers the first of them (its time is first_frame / 60 s), for runs rendered in
// several calls.
RunRecord render_headless_frames(SandboxFrame& frame, vk::FrameRing& ring, uint32_t count,
                                 GpuTimeLog& gpu_times, bool progress = false, uint64_t first_frame = 0);

}  // namespace sg::sandbox
