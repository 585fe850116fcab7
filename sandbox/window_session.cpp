// SPDX-License-Identifier: MIT
#include "sandbox/window_session.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <thread>

#define GLFW_INCLUDE_VULKAN
#include <utility>

#include <GLFW/glfw3.h>

#include "rendergraph/device/context.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "rendergraph/device/swapchain.h"
#include "rendergraph/device/vulkan_error.h"
#include "sandbox/sandbox_frame.h"
#include "systems/frame/png.h"
#include "systems/scene/scene_queries.h"

namespace sg::sandbox {
namespace {

VkExtent2D framebuffer_extent(GLFWwindow* window) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window, &w, &h);
  return {static_cast<uint32_t>(w), static_cast<uint32_t>(h)};
}

}  // namespace

WindowSession::WindowSession(const Options& options)
    : options_(options),
      scene_(load_scene_view(options.frame, float(options.frame.width) / float(options.frame.height))) {
  pacer_.set_max_fps(options.max_fps);
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_ =
      glfwCreateWindow(int(options.frame.width), int(options.frame.height), "Shadowgraph", nullptr, nullptr);
  if (!window_) throw std::runtime_error("cannot create a GLFW window");
  // Key presses and wheel steps arrive as events; held keys and the cursor are polled (fly_input).
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
    auto* session = static_cast<WindowSession*>(glfwGetWindowUserPointer(w));
    if (key == GLFW_KEY_F && action == GLFW_PRESS) session->frame_scene_ = true;
    if (key == GLFW_KEY_P && action == GLFW_PRESS) session->screenshot_ = true;
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double steps) {
    static_cast<WindowSession*>(glfwGetWindowUserPointer(w))->scroll_ += float(steps);
  });
  glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
    if (count > 0) static_cast<WindowSession*>(glfwGetWindowUserPointer(w))->dropped_ = paths[count - 1];
  });

  vk::ContextOptions vulkan_options = context_options(options.frame);
  vulkan_options.presentation = true;
  uint32_t extension_count = 0;
  const char** extensions = glfwGetRequiredInstanceExtensions(&extension_count);
  if (!extensions) throw std::runtime_error("GLFW found no Vulkan window support on this system");
  vulkan_options.instance_extensions.assign(extensions, extensions + extension_count);
  context_ = std::make_unique<vk::VulkanContext>(vulkan_options);

  VkSurfaceKHR surface = VK_NULL_HANDLE;
  vk::check(glfwCreateWindowSurface(context_->instance(), window_, nullptr, &surface),
            "glfwCreateWindowSurface");
  swapchain_ = std::make_unique<vk::Swapchain>(
      *context_, surface, options.vsync ? vk::PresentMode::vsync : vk::PresentMode::no_vsync);
  frames_ = std::make_unique<vk::FrameRing>(*context_);
  frame_ = std::make_unique<SandboxFrame>(*context_, scene_, options, frames_->frames_in_flight(), window_);
  ready_ = fit_to_window();
  start_seconds_ = glfwGetTime();
  last_frame_seconds_ = start_seconds_;
}

WindowSession::~WindowSession() {
  if (frames_) frames_->wait_idle();
  frame_.reset();
  frames_.reset();
  swapchain_.reset();
  context_.reset();
  if (window_) glfwDestroyWindow(window_);
}

VkExtent2D WindowSession::swapchain_extent() const {
  return swapchain_->valid() ? swapchain_->extent() : VkExtent2D{0, 0};
}

bool WindowSession::fit_to_window() {
  // recreate() waits for the device to go idle, so the old frame image is free too.
  if (!swapchain_->recreate(framebuffer_extent(window_))) return false;
  frame_->fit(swapchain_->extent(), true);
  return true;
}

void WindowSession::open(const std::string& path) {
  const Options next = options_to_open(options_, path);
  const VkExtent2D extent = swapchain_extent();
  try {
    SceneView opened =
        load_scene_view(next.frame, float(std::max(extent.width, 1u)) / float(std::max(extent.height, 1u)));
    frames_->wait_idle();
    frame_.reset();
    scene_ = std::move(opened);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "shadowgraph: cannot open %s: %s\n", path.c_str(), error.what());
    return;
  }
  options_ = next;
  frame_ = std::make_unique<SandboxFrame>(*context_, scene_, options_, frames_->frames_in_flight(), window_);
  ready_ = fit_to_window();
  std::printf("shadowgraph: opened %s\n", scene_.scene.name.c_str());
}

void WindowSession::finish() {
  frames_->wait_idle();
  for (uint32_t slot = 0; slot < frames_->frames_in_flight(); ++slot) {
    frame_->frame().executor().collect_timings(slot);
    gpu_times_.add(frame_->frame().executor().latest_timings());
  }
}

FlyInput WindowSession::fly_input() {
  FlyInput input;
  const auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0f : 0.0f; };
  input.move = {held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                held(GLFW_KEY_W) - held(GLFW_KEY_S)};
  double x = 0.0;
  double y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  const glm::vec2 cursor(x, y);
  input.look = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  input.mouse_delta = last_cursor_ ? cursor - *last_cursor_ : glm::vec2(0.0f);
  last_cursor_ = cursor;
  input.scroll = std::exchange(scroll_, 0.0f);
  input.frame_scene = std::exchange(frame_scene_, false);
  return input;
}

FrameResult WindowSession::frame() {
  if (SandboxUi* ui = frame_->ui()) {
    if (std::optional<std::string> path = ui->take_open_request()) dropped_ = std::move(path);
  }
  if (std::optional<std::string> path = std::exchange(dropped_, std::nullopt)) open(*path);
  if (SandboxUi* ui = frame_->ui()) {
    pacer_.set_max_fps(ui->max_fps());
    if (std::optional<float> scale = ui->take_render_scale_request()) {
      frame_->set_render_scale(*scale);
      rescale_ = true;
    }
  }
  if (std::exchange(rescale_, false) && ready_) {
    frames_->wait_idle();  // the frame's images are made anew
    frame_->fit(swapchain_extent(), true);
  }
  std::this_thread::sleep_for(pacer_.wait(FramePacer::Clock::now()));
  glfwPollEvents();
  if (glfwWindowShouldClose(window_)) return FrameResult::closed;
  const VkExtent2D extent = framebuffer_extent(window_);
  if (extent.width == 0 || extent.height == 0) {
    ready_ = false;
    glfwWaitEventsTimeout(0.1);  // minimized: sleep until something happens
    return FrameResult::minimized;
  }
  const VkExtent2D current = swapchain_extent();
  if (!ready_ || extent.width != current.width || extent.height != current.height) {
    ready_ = fit_to_window();
    return ready_ ? FrameResult::swapchain_recreated : FrameResult::minimized;
  }

  vk::FrameSlot& frame = frame_->frame().begin(*frames_);
  const std::optional<uint32_t> image = swapchain_->acquire(frame.image_acquired);
  if (!image) {
    ready_ = false;
    return FrameResult::swapchain_recreated;
  }
  const auto start = std::chrono::steady_clock::now();  // after the waits for the GPU
  const double now = glfwGetTime();
  FlyInput input = fly_input();
  if (frame_->ui_wants_input()) input = FlyInput{};  // the panels have the mouse or keyboard
  scene::Aabb bounds;
  if (input.frame_scene) {
    if (frame_->ui() != nullptr) bounds = frame_->ui()->selection_bounds(scene_.scene.world);
    if (bounds.empty()) bounds = scene::scene_bounds(scene_.scene);
  }
  fly(fly_camera_, scene_.pose, input, static_cast<float>(now - last_frame_seconds_), bounds,
      scene_.lens.yfov);
  last_frame_seconds_ = now;
  frame_->frame().record(
      frame, now - start_seconds_,
      PresentTarget{swapchain_->image(*image), swapchain_->format(), swapchain_->extent()});
  const vk::SemaphoreWait wait{frame.image_acquired, acquire_wait_stage};
  const VkSemaphore signal = swapchain_->render_finished(*image);
  frames_->submit({&wait, 1}, {&signal, 1});
  frame_ms_.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  if (!swapchain_->present(*image)) ready_ = false;
  const auto presented = std::chrono::steady_clock::now();
  if (last_present_) {
    wall_frame_ms_.push_back(std::chrono::duration<double, std::milli>(presented - *last_present_).count());
  }
  last_present_ = presented;
  const std::optional<vk::FrameTimings>& timings = frame_->frame().executor().latest_timings();
  if (gpu_times_.add(timings) && frame_->adapt_render_scale(*timings)) {
    rescale_ = true;  // at the next frame's start
  }
  if (std::exchange(screenshot_, false)) {
    frames_->wait_idle();
    const std::string path = "shadowgraph-" + std::to_string(++screenshots_) + ".png";
    write_png(path, vk::read_rgba8(*context_, frame_->frame().image()));
    std::printf("shadowgraph: wrote %s\n", path.c_str());
  }
  return FrameResult::rendered;
}

}  // namespace sg::sandbox
