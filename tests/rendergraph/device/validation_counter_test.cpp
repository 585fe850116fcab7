// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

// The counter that every GPU test relies on must itself catch a real API misuse.
TEST(ValidationCounter, CountsADeliberateMisuse) {
  vk::VulkanContext context(validated_options());
  ASSERT_EQ(context.validation_errors(), 0u);
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 0;  // VUID-VkBufferCreateInfo-size-00912: size must be greater than 0
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  std::fprintf(stderr, "(the validation error below is expected)\n");
  const VkResult result = vkCreateBuffer(context.device(), &info, nullptr, &buffer);
  if (result == VK_SUCCESS && buffer != VK_NULL_HANDLE) vkDestroyBuffer(context.device(), buffer, nullptr);
  EXPECT_GE(context.validation_errors(), 1u);
}

TEST(ValidationCounter, CleanUsageCountsNothing) {
  vk::VulkanContext context(validated_options());
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 64;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateBuffer(context.device(), &info, nullptr, &buffer), VK_SUCCESS);
  vkDestroyBuffer(context.device(), buffer, nullptr);
  EXPECT_EQ(context.validation_errors(), 0u);
}

}  // namespace
}  // namespace sg::test
