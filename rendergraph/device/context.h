// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan instance and device every other part of the engine renders with.
//
// Contract: one graphics+compute queue; Vulkan 1.3 with dynamic rendering and
// synchronization2 required; every required feature is checked and a missing one is reported
// by name. With validation on, the Khronos validation layer reports through a debug messenger
// that prints each message and counts errors, so tests can fail on any.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/device_features.h"
#include "rendergraph/device/gpu_allocator.h"
#include "rendergraph/device/pipeline_statistics.h"

namespace sg::vk {

struct ContextOptions {
  bool validation = false;                       // Khronos validation layer + debug messenger
  bool synchronization_validation = false;       // also check barriers (implies validation)
  std::string device_name;                       // case-insensitive substring; empty: best type
  std::vector<std::string> instance_extensions;  // e.g. the window system's surface extensions
  bool presentation = false;                     // enable VK_KHR_swapchain on the device
  // Keep every pipeline's compiler statistics (pipeline_statistics.h) where the device reports
  // them; a device that does not is used all the same, and the log says so.
  bool pipeline_statistics = false;
};

// Whether `device` offers the device extension `name`.
bool has_device_extension(VkPhysicalDevice device, const char* name);

// True when SHADOWGRAPH_VALIDATION is set to something other than "0" in the environment.
bool validation_requested_by_environment();

struct PhysicalDeviceInfo {
  std::string name;
  VkPhysicalDeviceType type;
  uint32_t api_version;
};
// Every Vulkan device the loader sees, for listings and error messages.
std::vector<PhysicalDeviceInfo> list_physical_devices(VkInstance instance);

class VulkanContext {
 public:
  explicit VulkanContext(const ContextOptions& options);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  std::string device_name() const { return properties_.deviceName; }
  GpuAllocator& allocator() { return *allocator_; }
  // The optional features this device has, all of them enabled.
  const OptionalFeatures& optional_features() const { return optional_features_; }

  // The pipelines' statistics, where ContextOptions::pipeline_statistics asked for them and the
  // device reports them; null otherwise. Pipelines built on this context add to it.
  PipelineStatisticsLog* pipeline_statistics() const { return pipeline_statistics_.get(); }

  bool validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }
  uint32_t validation_errors() const { return validation_errors_.load(); }
  uint32_t validation_warnings() const { return validation_warnings_.load(); }

  // Debug labels and object names (VK_EXT_debug_utils); no-ops when it is unavailable.
  void begin_label(VkCommandBuffer cmd, const char* name) const;
  void end_label(VkCommandBuffer cmd) const;
  void set_name(VkObjectType type, uint64_t handle, const char* name) const;

  // Records commands into a one-time command buffer, submits them and waits: for uploads and
  // readbacks at load time, never inside a frame.
  void submit_and_wait(const std::function<void(VkCommandBuffer)>& record);

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(
      VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
      const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

  void create_instance(const ContextOptions& options);
  void create_device(const ContextOptions& options);
  void release();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  OptionalFeatures optional_features_;
  VkCommandPool one_time_pool_ = VK_NULL_HANDLE;
  std::unique_ptr<GpuAllocator> allocator_;
  std::unique_ptr<PipelineStatisticsLog> pipeline_statistics_;

  PFN_vkCmdBeginDebugUtilsLabelEXT cmd_begin_label_ = nullptr;
  PFN_vkCmdEndDebugUtilsLabelEXT cmd_end_label_ = nullptr;
  PFN_vkSetDebugUtilsObjectNameEXT set_object_name_ = nullptr;

  std::atomic<uint32_t> validation_errors_{0};
  std::atomic<uint32_t> validation_warnings_{0};
};

}  // namespace sg::vk
