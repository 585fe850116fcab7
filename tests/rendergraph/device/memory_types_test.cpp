// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <initializer_list>

#include "rendergraph/device/gpu_allocator.h"

namespace sg::vk {
namespace {

constexpr VkMemoryPropertyFlags device_local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
constexpr VkMemoryPropertyFlags host =
    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
constexpr VkMemoryPropertyFlags cached = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
constexpr uint32_t every_type = ~0u;

VkPhysicalDeviceMemoryProperties types(std::initializer_list<VkMemoryPropertyFlags> flags) {
  VkPhysicalDeviceMemoryProperties properties{};
  for (const VkMemoryPropertyFlags f : flags)
    properties.memoryTypes[properties.memoryTypeCount++].propertyFlags = f;
  return properties;
}

// A discrete GPU with resizable BAR lists its host memory types before the device-local one the
// CPU maps, as NVIDIA's drivers do: the first host-visible type would be read over the bus.
TEST(MemoryTypes, StreamedDataTakesTheDeviceLocalMemoryTheCpuMaps) {
  const VkPhysicalDeviceMemoryProperties gpu =
      types({device_local, host, host | cached, device_local | host});
  EXPECT_EQ(choose_memory_type(gpu, every_type, MemoryUsage::gpu_only), 0u);
  EXPECT_EQ(choose_memory_type(gpu, every_type, MemoryUsage::upload), 1u);
  EXPECT_EQ(choose_memory_type(gpu, every_type, MemoryUsage::readback), 2u);
  EXPECT_EQ(choose_memory_type(gpu, every_type, MemoryUsage::stream), 3u);
  // A resource the mapped device-local type cannot hold streams from host memory.
  EXPECT_EQ(choose_memory_type(gpu, 0b0111u, MemoryUsage::stream), 1u);
}

TEST(MemoryTypes, WithoutMappedDeviceMemoryStreamedDataLiesInHostMemory) {
  const VkPhysicalDeviceMemoryProperties gpu = types({device_local, host | cached, host});
  EXPECT_EQ(choose_memory_type(gpu, every_type, MemoryUsage::stream), 1u);
  EXPECT_EQ(choose_memory_type(gpu, every_type, MemoryUsage::upload), 1u);
}

// A CPU driver's one type is everything at once; gpu_only takes it too.
TEST(MemoryTypes, ACpuDriversOneTypeServesEveryUsage) {
  const VkPhysicalDeviceMemoryProperties cpu = types({device_local | host | cached});
  for (const MemoryUsage usage :
       {MemoryUsage::gpu_only, MemoryUsage::upload, MemoryUsage::readback, MemoryUsage::stream}) {
    EXPECT_EQ(choose_memory_type(cpu, every_type, usage), 0u);
  }
  const VkPhysicalDeviceMemoryProperties host_only = types({host});
  EXPECT_EQ(choose_memory_type(host_only, every_type, MemoryUsage::gpu_only), 0u);
}

TEST(MemoryTypes, NoAllowedTypeIsRefused) {
  const VkPhysicalDeviceMemoryProperties gpu = types({device_local, host});
  EXPECT_EQ(choose_memory_type(gpu, 0b01u, MemoryUsage::stream), UINT32_MAX);
  EXPECT_EQ(choose_memory_type(gpu, 0u, MemoryUsage::gpu_only), UINT32_MAX);
}

}  // namespace
}  // namespace sg::vk
