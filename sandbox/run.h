#pragma once
// The sandbox's two ways to run the same frame: offscreen (a PNG at the end) or in a window.
#include <vector>

#include "sandbox/options.h"

namespace sg {
class SceneRenderer;
namespace vk {
class VulkanContext;
}
}  // namespace sg

namespace sg::sandbox {

// Both return the process exit code; errors are thrown as exceptions.
int run_headless(const Options& options);
int run_windowed(const Options& options);

// Shared ending: writes the screenshot if one was asked for, prints a summary of the run,
// and returns 0, or 3 when the validation layer reported errors.
int finish_run(const Options& options, vk::VulkanContext& context, const SceneRenderer& renderer,
               const std::vector<double>& frame_ms);

}  // namespace sg::sandbox
