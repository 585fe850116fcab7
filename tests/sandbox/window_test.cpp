// SPDX-License-Identifier: MIT
// Window-system tests. They need an X or Wayland display (CI runs the suite under Xvfb) and
// are skipped without one.
#include <cmath>
#include <cstdlib>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "rendergraph/device/swapchain.h"
#include "rendergraph/device/vulkan_error.h"
#include "sandbox/sandbox_frame.h"
#include "sandbox/window_session.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

class WindowTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if (!(display && *display) && !(wayland && *wayland)) GTEST_SKIP() << "no display";
    ASSERT_TRUE(glfwInit()) << "a display is set but GLFW cannot open it";
  }
  void TearDown() override { glfwTerminate(); }
};

sandbox::FrameResult render_until_rendered(sandbox::WindowSession& session) {
  sandbox::FrameResult result = sandbox::FrameResult::closed;
  for (int i = 0; i < 20; ++i) {
    result = session.frame();
    if (result == sandbox::FrameResult::rendered) break;
  }
  return result;
}

TEST_F(WindowTest, SwapchainFollowsWindowResize) {
  sandbox::Options options;
  options.frame.width = 200;
  options.frame.height = 150;
  options.frame.validation = true;
  sandbox::WindowSession session(options);
  ASSERT_EQ(render_until_rendered(session), sandbox::FrameResult::rendered);
  EXPECT_EQ(session.swapchain_extent().width, 200u);
  EXPECT_EQ(session.swapchain_extent().height, 150u);

  glfwSetWindowSize(session.window(), 320, 240);
  for (int i = 0; i < 50 && session.swapchain_extent().width != 320; ++i) session.frame();
  EXPECT_EQ(session.swapchain_extent().width, 320u);
  EXPECT_EQ(session.swapchain_extent().height, 240u);
  EXPECT_EQ(render_until_rendered(session), sandbox::FrameResult::rendered);
  EXPECT_EQ(session.context().validation_errors(), 0u);
}

// The sandbox's window as a person treats it: resized smaller and larger, minimized and
// restored, with the panels on, every frame under validation. Without a window manager (plain
// Xvfb, as in CI) iconifying does nothing, so there the minimized state is covered by the
// zero-sized swapchain test below.
TEST_F(WindowTest, TheSandboxSurvivesResizeMinimizeAndRestore) {
  sandbox::Options options;
  options.frame.width = 200;
  options.frame.height = 150;
  options.frame.validation = true;
  options.ui = true;
  sandbox::WindowSession session(options);
  ASSERT_EQ(render_until_rendered(session), sandbox::FrameResult::rendered);
  for (const auto& [w, h] : {std::pair{120, 90}, std::pair{333, 211}, std::pair{64, 300}}) {
    glfwSetWindowSize(session.window(), w, h);
    for (int i = 0; i < 50 && session.swapchain_extent().width != uint32_t(w); ++i) session.frame();
    EXPECT_EQ(session.swapchain_extent().width, uint32_t(w));
    EXPECT_EQ(session.swapchain_extent().height, uint32_t(h));
    EXPECT_EQ(render_until_rendered(session), sandbox::FrameResult::rendered);
    // A CPU device's window draws the scene at its render scale, the frame at its own size.
    const Frame& frame = session.sandbox_frame().frame();
    const float scale = session.sandbox_frame().render_scale();
    EXPECT_EQ(frame.image().extent().width, uint32_t(w));
    EXPECT_EQ(frame.scene_extent().width, uint32_t(std::lround(w * scale)));
    EXPECT_EQ(frame.scene_extent().height, uint32_t(std::lround(h * scale)));
  }
  glfwIconifyWindow(session.window());
  for (int i = 0; i < 5; ++i) session.frame();
  glfwRestoreWindow(session.window());
  EXPECT_EQ(render_until_rendered(session), sandbox::FrameResult::rendered);
  session.finish();
  EXPECT_EQ(session.context().validation_errors(), 0u);
}

// In a CPU device's window without a chosen render scale the scene starts at half the window's
// size and follows the frame time (RenderScaleControl): a small window's frames are short, so
// it steps up to full size, and says so in --stats.
TEST_F(WindowTest, TheRenderScaleFollowsTheFrameTime) {
  sandbox::Options options;
  options.frame.width = 160;
  options.frame.height = 120;
  options.frame.scene = "point-room";
  sandbox::WindowSession session(options);
  ASSERT_EQ(render_until_rendered(session), sandbox::FrameResult::rendered);
  const Frame& frame = session.sandbox_frame().frame();
  EXPECT_EQ(session.sandbox_frame().render_scale(), 0.5f);
  EXPECT_EQ(frame.scene_extent().width, 80u);
  for (int i = 0; i < 400 && session.sandbox_frame().render_scale() < 1.0f; ++i) session.frame();
  EXPECT_EQ(session.sandbox_frame().render_scale(), 1.0f);
  EXPECT_EQ(session.sandbox_frame().render_scale_changes(), 2u) << "0.5 -> 0.7 -> 1";
  EXPECT_EQ(frame.scene_extent().width, 160u);
  EXPECT_EQ(frame.scene_extent().height, 120u);
  session.finish();
}

// A minimized window has a zero-sized framebuffer: the swapchain must go away rather than
// fail, and come back when the window does.
TEST_F(WindowTest, ZeroExtentDropsTheSwapchainUntilRestored) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  GLFWwindow* window = glfwCreateWindow(160, 120, "swapchain test", nullptr, nullptr);
  ASSERT_NE(window, nullptr);
  {
    vk::ContextOptions options = validated_options();
    options.presentation = true;
    uint32_t count = 0;
    const char** extensions = glfwGetRequiredInstanceExtensions(&count);
    options.instance_extensions.assign(extensions, extensions + count);
    vk::VulkanContext context(options);
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    ASSERT_EQ(glfwCreateWindowSurface(context.instance(), window, nullptr, &surface), VK_SUCCESS);
    vk::Swapchain swapchain(context, surface, vk::PresentMode::vsync);
    EXPECT_TRUE(swapchain.recreate({160, 120}));
    EXPECT_TRUE(swapchain.valid());
    EXPECT_FALSE(swapchain.recreate({0, 0}));
    EXPECT_FALSE(swapchain.valid());
    EXPECT_TRUE(swapchain.recreate({160, 120}));
    EXPECT_TRUE(swapchain.valid());
    EXPECT_EQ(context.validation_errors(), 0u);
  }
  glfwDestroyWindow(window);
}

}  // namespace
}  // namespace sg::test
