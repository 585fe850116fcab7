#pragma once
// The sandbox's two ways to run the same frame: offscreen (a PNG at the end) or in a window.
#include <vector>

#include "rendergraph/device/fwd.h"
#include "sandbox/options.h"

namespace sg::sandbox {

class GpuTimeLog;
class SandboxFrame;
struct SandboxScene;

// Both return the process exit code; errors are thrown as exceptions.
int run_headless(const Options& options);
int run_windowed(const Options& options);

// What a run measured, for the summary and --stats.
struct RunRecord {
  // Per rendered frame: CPU time to update, build, compile, record and submit it, not counting
  // waits for the GPU (the frame ring's fence, the swapchain's acquire and present).
  std::vector<double> cpu_frame_ms;
  // Elapsed time per frame, waits included: present to present in a window (after the first
  // frame), frame start to frame start headless (the last frame: to the GPU going idle).
  std::vector<double> wall_frame_ms;
  const GpuTimeLog* gpu_times = nullptr;
};

// Shared ending: writes the screenshot and the --stats file if asked for, prints a summary of
// the run, and returns 0, or 3 when the validation layer reported errors.
int finish_run(const Options& options, vk::VulkanContext& context, const SandboxScene& scene,
               SandboxFrame& frame, const RunRecord& record);

}  // namespace sg::sandbox
