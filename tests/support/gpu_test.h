// SPDX-License-Identifier: MIT
#pragma once
// Test helpers: every GPU test runs on a context with the Khronos validation layer and
// synchronization validation on, and fails if the layer reported any error.
#include <gtest/gtest.h>

#include "rendergraph/device/context.h"

namespace sg::test {

inline vk::ContextOptions validated_options() {
  vk::ContextOptions options;
  options.validation = true;
  options.synchronization_validation = true;
  return options;
}

class GpuTest : public ::testing::Test {
 protected:
  void TearDown() override {
    EXPECT_EQ(context.validation_errors(), 0u) << "the Vulkan validation layer reported errors";
  }
  vk::VulkanContext context{validated_options()};
};

}  // namespace sg::test
