// SPDX-License-Identifier: MIT
#pragma once
// The sandbox's two ways to run the same frame: offscreen (a PNG at the end) or in a window.
#include "rendergraph/device/fwd.h"
#include "sandbox/options.h"
#include "systems/frame/headless_frames.h"

namespace sg {
struct SceneView;
}

namespace sg::sandbox {

class SandboxFrame;

// Both return the process exit code; errors are thrown as exceptions.
int run_headless(const Options& options);
int run_windowed(const Options& options);

// Shared ending: writes the screenshot, export, shadow maps and --stats file asked for, each
// whatever became of the others, prints a summary of the run, and returns 0, 3 when the
// validation layer reported errors, 1 when an output could not be written, or 130 when a
// signal ended the run early (interrupt.h).
int finish_run(const Options& options, vk::VulkanContext& context, const SceneView& scene,
               SandboxFrame& frame, const RunRecord& record);

}  // namespace sg::sandbox
