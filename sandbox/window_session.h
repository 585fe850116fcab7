#pragma once
// A window showing the scene: GLFW window, Vulkan context with presentation, swapchain,
// renderer. The swapchain follows the window's framebuffer size; while the window is
// minimized (zero-sized framebuffer) frames are skipped rather than rendered.
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "sandbox/options.h"
#include "systems/builtin_scene.h"

struct GLFWwindow;

namespace sg {
class SceneRenderer;
namespace vk {
class FrameRing;
class Swapchain;
class VulkanContext;
}  // namespace vk
}  // namespace sg

namespace sg::sandbox {

enum class FrameResult { rendered, minimized, swapchain_recreated, closed };

// glfwInit must have succeeded before a session is created.
class WindowSession {
 public:
  explicit WindowSession(const Options& options);
  ~WindowSession();

  // Handles window events, then renders and presents one frame when the window can show one.
  FrameResult frame();

  GLFWwindow* window() const { return window_; }
  vk::VulkanContext& context() { return *context_; }
  const SceneRenderer& renderer() const { return *renderer_; }
  VkExtent2D swapchain_extent() const;
  const std::vector<double>& frame_ms() const { return frame_ms_; }

 private:
  bool fit_to_window();

  GLFWwindow* window_ = nullptr;
  BuiltinScene scene_;
  std::unique_ptr<vk::VulkanContext> context_;
  std::unique_ptr<vk::Swapchain> swapchain_;
  std::unique_ptr<SceneRenderer> renderer_;
  std::unique_ptr<vk::FrameRing> frames_;
  bool ready_ = false;
  std::vector<double> frame_ms_;
};

}  // namespace sg::sandbox
