// SPDX-License-Identifier: MIT
#pragma once
// A window showing the scene: GLFW window, Vulkan context with presentation, swapchain, the
// sandbox's frame graph. The swapchain follows the window's framebuffer size; while the window is
// minimized (zero-sized framebuffer) frames are skipped rather than rendered.
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/fwd.h"
#include "sandbox/fly_camera.h"
#include "sandbox/frame_pacer.h"
#include "sandbox/options.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/scene_view.h"

struct GLFWwindow;

namespace sg::sandbox {

class SandboxFrame;

enum class FrameResult { rendered, minimized, swapchain_recreated, closed };

// glfwInit must have succeeded before a session is created.
// Esc closes the window, P writes shadowgraph-N.png in the working folder; the fly camera
// (fly_camera.h) moves the view, and F frames the light selected in the panels, or the scene. A
// .gltf or .glb file dropped on the window (or opened from the Frame panel) replaces the scene.
class WindowSession {
 public:
  explicit WindowSession(const Options& options);
  ~WindowSession();

  // Handles window events, then renders and presents one frame when the window can show one.
  FrameResult frame();
  // Waits for the GPU and takes the timings of the frames still in flight.
  void finish();

  GLFWwindow* window() const { return window_; }
  vk::VulkanContext& context() { return *context_; }
  SceneView& scene() { return scene_; }
  const SandboxFrame& sandbox_frame() const { return *frame_; }
  SandboxFrame& sandbox_frame() { return *frame_; }
  VkExtent2D swapchain_extent() const;
  const std::vector<double>& frame_ms() const { return frame_ms_; }
  // Present to present, after the first frame.
  const std::vector<double>& wall_frame_ms() const { return wall_frame_ms_; }
  const GpuTimeLog& gpu_times() const { return gpu_times_; }

 private:
  bool fit_to_window();
  // Replaces the scene by the one at `path` (options_to_open); on a load error the scene stays
  // and the error is printed.
  void open(const std::string& path);
  FlyInput fly_input();

  GLFWwindow* window_ = nullptr;
  Options options_;  // the current scene's
  SceneView scene_;
  std::optional<std::string> dropped_;  // the last file dropped since the last frame
  std::unique_ptr<vk::VulkanContext> context_;
  std::unique_ptr<vk::Swapchain> swapchain_;
  std::unique_ptr<vk::FrameRing> frames_;
  std::unique_ptr<SandboxFrame> frame_;
  bool ready_ = false;
  double start_seconds_ = 0.0;
  double last_frame_seconds_ = 0.0;
  FlyCamera fly_camera_;
  std::optional<glm::vec2> last_cursor_;
  float scroll_ = 0.0f;       // wheel steps since the last frame
  bool frame_scene_ = false;  // F pressed since the last frame
  bool screenshot_ = false;   // P pressed since the last frame
  bool rescale_ = false;      // the render scale changed since the last frame
  int screenshots_ = 0;
  std::vector<double> frame_ms_;
  std::vector<double> wall_frame_ms_;
  std::optional<std::chrono::steady_clock::time_point> last_present_;
  FramePacer pacer_;
  GpuTimeLog gpu_times_;
};

}  // namespace sg::sandbox
