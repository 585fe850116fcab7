// SPDX-License-Identifier: MIT
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rendergraph/device/barriers.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/device/upload.h"
#include "rendergraph/device/vulkan_error.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

using ContextTest = GpuTest;

TEST_F(ContextTest, CreatesVulkan13DeviceWithValidation) {
  EXPECT_NE(context.device(), VK_NULL_HANDLE);
  EXPECT_NE(context.queue(), VK_NULL_HANDLE);
  EXPECT_GE(context.properties().apiVersion, VK_API_VERSION_1_3);
  EXPECT_TRUE(context.validation_enabled());
  EXPECT_FALSE(context.device_name().empty());
}

TEST(ContextSelection, UnknownDeviceNameListsTheDevicesSeen) {
  vk::ContextOptions options = validated_options();
  options.device_name = "no-such-gpu";
  try {
    vk::VulkanContext context(options);
    FAIL() << "a context was created for a device that does not exist";
  } catch (const vk::VulkanError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no suitable Vulkan device matching \"no-such-gpu\""), std::string::npos)
        << message;
    EXPECT_NE(message.find("name does not contain"), std::string::npos) << message;
  }
}

TEST(ContextSelection, NameSubstringIsCaseInsensitive) {
  std::string name;
  {
    vk::VulkanContext any(validated_options());
    name = any.device_name();
  }
  vk::ContextOptions options = validated_options();
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  options.device_name = name.substr(0, 4);
  vk::VulkanContext context(options);
  EXPECT_EQ(context.validation_errors(), 0u);
}

TEST_F(ContextTest, SmallBuffersShareOneMemoryBlock) {
  std::vector<vk::Buffer> buffers;
  for (int i = 0; i < 200; ++i) {
    buffers.emplace_back(context, vk::BufferDesc{4096, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                 vk::MemoryUsage::gpu_only, "small"});
  }
  vk::MemoryStats stats = context.allocator().stats();
  EXPECT_EQ(stats.block_count, 1u);
  EXPECT_EQ(stats.allocation_count, 200u);
  EXPECT_GE(stats.used_bytes, 200u * 4096u);
  buffers.clear();
  stats = context.allocator().stats();
  EXPECT_EQ(stats.allocation_count, 0u);
  EXPECT_EQ(stats.used_bytes, 0u);
}

TEST_F(ContextTest, ResourceLargerThanABlockGetsItsOwnBlock) {
  const VkDeviceSize big = vk::GpuAllocator::default_block_size + 4096;
  vk::Buffer small(context, {256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::gpu_only, "s"});
  vk::Buffer large(context, {big, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::gpu_only, "l"});
  const vk::MemoryStats stats = context.allocator().stats();
  EXPECT_EQ(stats.block_count, 2u);
  EXPECT_GE(stats.reserved_bytes, big + vk::GpuAllocator::default_block_size);
}

// The VmFlags of the mapping holding `address` in /proc/self/smaps; empty when none is found.
std::string mapping_flags(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= at && at < end;
    } else if (inside && line.starts_with("VmFlags:")) {
      return line;
    }
  }
  return {};
}

TEST_F(ContextTest, CpuDeviceBlocksAskForHugePages) {
  if (context.properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU)
    GTEST_SKIP() << "a GPU's memory is its own";
  if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage") ||
      !std::filesystem::exists("/proc/self/smaps")) {
    GTEST_SKIP() << "no transparent huge pages here";
  }
  vk::Buffer buffer(context, {1 << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::upload, "huge"});
  ASSERT_NE(buffer.mapped(), nullptr);
  const std::string flags = mapping_flags(buffer.mapped());
  ASSERT_FALSE(flags.empty()) << "no mapping holds the buffer's memory";
  EXPECT_NE((flags + " ").find(" hg "), std::string::npos) << flags;
}

TEST_F(ContextTest, StagedUploadReachesDeviceLocalBuffer) {
  std::vector<uint32_t> data(10000);
  for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<uint32_t>(i * 2654435761u);
  const VkDeviceSize bytes = data.size() * sizeof(uint32_t);
  vk::Buffer device_buffer(context,
                           {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                            vk::MemoryUsage::gpu_only, "device"});
  vk::Buffer host_buffer(context,
                         {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::readback, "host"});
  vk::UploadBatch upload(context);
  upload.copy(device_buffer, std::span<const uint32_t>(data));
  upload.submit();
  context.submit_and_wait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, device_buffer.handle(), host_buffer.handle(), 1, &region);
    vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  });
  EXPECT_EQ(std::memcmp(host_buffer.mapped(), data.data(), bytes), 0);
}

TEST_F(ContextTest, UploadPastTheEndIsRefused) {
  vk::Buffer buffer(context, {16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::gpu_only, "tiny"});
  vk::UploadBatch upload(context);
  const uint32_t data[8] = {};
  EXPECT_THROW(upload.copy(buffer, std::span<const uint32_t>(data)), vk::VulkanError);
}

}  // namespace
}  // namespace sg::test
