// SPDX-License-Identifier: MIT
// The shadow atlas's comparison filter: linear where the device filters the depth format, nearest
// where it cannot, and the renderer telling which (Debian 12's lavapipe cannot filter d32_sfloat).
#include <string_view>

#include <gtest/gtest.h>

#include "rendergraph/vulkan/plan_translation.h"
#include "systems/frame/frame.h"
#include "systems/frame/scene_view.h"
#include "systems/lighting/light_resources.h"
#include "systems/renderer/scene_renderer.h"
#include "systems/shadow_maps/shadow_atlas.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

TEST(ComparisonFilter, IsLinearOnlyWhereTheFormatFilters) {
  EXPECT_EQ(comparison_filter(VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                              VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT),
            VK_FILTER_LINEAR);
  EXPECT_EQ(
      comparison_filter(VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT),
      VK_FILTER_NEAREST);
}

using RendererComparisonFilter = GpuTest;

TEST_F(RendererComparisonFilter, FollowsTheDevicesDepthFormat) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), vk::to_vk(ShadowAtlas::depth_format),
                                      &properties);
  const bool filters =
      (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
  FrameSettings options;
  const SceneView view = load_scene_view(options, 16.0f / 9.0f);
  const SceneRenderer renderer(context, view.scene, 2, frame_format, options.renderer);
  EXPECT_EQ(renderer.shadow_comparisons_filtered(), filters);
  // Mesa writes its version as the driver's: 22 is Debian 12's lavapipe, which the README's note
  // on the kernels names. Mesa 25's (Debian 13) filters the format.
  const VkPhysicalDeviceProperties& device = context.properties();
  if (std::string_view(device.deviceName).starts_with("llvmpipe") &&
      VK_API_VERSION_MAJOR(device.driverVersion) == 22) {
    EXPECT_FALSE(filters)
        << "Debian 12's lavapipe filters d32_sfloat now: the README's note on its kernels is out of date";
  }
}

}  // namespace
}  // namespace sg::test
