// SPDX-License-Identifier: MIT
#include "rendergraph/device/context.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#ifdef SHADOWGRAPH_SANITIZE
#include <dlfcn.h>
#endif

#include "rendergraph/device/device_features.h"
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {
namespace {

constexpr const char* validation_layer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(),
                     [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool has_instance_extension(const char* name, const char* layer = nullptr) {
  uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(layer, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

std::string lowercase(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// Discrete GPUs first, then integrated, virtual and CPU implementations.
int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
  }
}

const char* type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

std::string version_string(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

// Why `device` cannot run the engine, or empty when it can.
std::vector<std::string> disqualifications(VkPhysicalDevice device, bool presentation,
                                           uint32_t& queue_family) {
  std::vector<std::string> reasons;
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(device, &props);
  if (props.apiVersion < VK_API_VERSION_1_3) {
    reasons.push_back("supports Vulkan " + version_string(props.apiVersion) + ", needs 1.3");
    return reasons;
  }
  DeviceFeatures features;
  query_features(device, features);
  reasons = missing_required_features(features);

  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  constexpr VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  queue_family = UINT32_MAX;
  for (uint32_t i = 0; i < count && queue_family == UINT32_MAX; ++i) {
    // Timestamps are needed for per-pass GPU timings.
    if ((families[i].queueFlags & needed) == needed && families[i].timestampValidBits > 0) {
      queue_family = i;
    }
  }
  if (queue_family == UINT32_MAX) reasons.push_back("no graphics+compute queue with timestamps");

  if (presentation && !has_device_extension(device, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) {
    reasons.push_back("no VK_KHR_swapchain (cannot present to a window)");
  }
  return reasons;
}

// The loader unloads the driver and layers at vkDestroyInstance; LeakSanitizer then cannot
// name the library behind their one-time allocations, so tests/lsan.supp cannot silence them.
// Pinning lavapipe and the validation layer keeps them named. Sanitizer builds only.
void keep_cpu_driver_and_layer_loaded() {
#ifdef SHADOWGRAPH_SANITIZE
  static const bool pinned = [] {
    dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE);
    dlopen("libVkLayer_khronos_validation.so", RTLD_NOW | RTLD_NODELETE);
    return true;
  }();
  (void)pinned;
#endif
}

}  // namespace

bool has_device_extension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

bool validation_requested_by_environment() {
  const char* value = std::getenv("SHADOWGRAPH_VALIDATION");
  return value != nullptr && *value != '\0' && std::strcmp(value, "0") != 0;
}

std::vector<PhysicalDeviceInfo> list_physical_devices(VkInstance instance) {
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  std::vector<PhysicalDeviceInfo> infos;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    infos.push_back({p.deviceName, p.deviceType, p.apiVersion});
  }
  return infos;
}

VulkanContext::VulkanContext(const ContextOptions& options) {
  keep_cpu_driver_and_layer_loaded();
  try {
    create_instance(options);
    create_device(options);
  } catch (...) {
    release();  // the destructor does not run for a constructor that throws
    throw;
  }
}

VulkanContext::~VulkanContext() { release(); }

void VulkanContext::release() {
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    allocator_.reset();
    if (one_time_pool_ != VK_NULL_HANDLE) vkDestroyCommandPool(device_, one_time_pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_ != VK_NULL_HANDLE) {
    vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

VKAPI_ATTR VkBool32 VKAPI_CALL VulkanContext::on_validation_message(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<VulkanContext*>(user);
  const char* label = "info";
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    self->validation_errors_.fetch_add(1);
    label = "ERROR";
  } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    self->validation_warnings_.fetch_add(1);
    label = "warning";
  }
  std::fprintf(stderr, "[vulkan validation %s] %s\n", label, data->pMessage);
  return VK_FALSE;  // never abort the call: the counters decide what fails
}

void VulkanContext::create_instance(const ContextOptions& options) {
  const bool validation = options.validation || options.synchronization_validation;
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  for (const std::string& e : options.instance_extensions) extensions.push_back(e.c_str());

  const bool debug_utils = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (debug_utils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (validation) {
    if (!has_layer(validation_layer)) {
      throw VulkanError(std::string("validation was requested but the Khronos validation layer (") +
                        validation_layer +
                        ") is not installed; on Debian: apt-get install vulkan-validationlayers");
    }
    if (!debug_utils) throw VulkanError("validation needs VK_EXT_debug_utils, which is missing");
    layers.push_back(validation_layer);
  }

  const VkValidationFeatureEnableEXT sync_feature =
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT validation_features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  validation_features.enabledValidationFeatureCount = 1;
  validation_features.pEnabledValidationFeatures = &sync_feature;
  const bool sync = options.synchronization_validation &&
                    has_instance_extension(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME, validation_layer);
  if (sync) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);

  VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = &VulkanContext::on_validation_message;
  messenger_info.pUserData = this;
  // Chained into instance creation too, so errors in vkCreateInstance itself are counted.
  if (sync) messenger_info.pNext = &validation_features;

  uint32_t loader_version = VK_API_VERSION_1_0;
  vkEnumerateInstanceVersion(&loader_version);
  if (loader_version < VK_API_VERSION_1_3) {
    throw VulkanError("the Vulkan loader supports " + version_string(loader_version) +
                      "; Shadowgraph needs Vulkan 1.3 (install libvulkan1 >= 1.3)");
  }

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "Shadowgraph";
  app.pEngineName = "Shadowgraph";
  app.apiVersion = VK_API_VERSION_1_3;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  if (validation) info.pNext = &messenger_info;
  check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance");

  if (validation) {
    messenger_info.pNext = nullptr;
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    check(create(instance_, &messenger_info, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
  }
  if (debug_utils) {
    cmd_begin_label_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance_, "vkCmdBeginDebugUtilsLabelEXT"));
    cmd_end_label_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance_, "vkCmdEndDebugUtilsLabelEXT"));
    set_object_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
  }
}

void VulkanContext::create_device(const ContextOptions& options) {
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance_, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance_, &count, devices.data());
  if (devices.empty()) {
    throw VulkanError(
        "no Vulkan device found; install a driver (on Debian, mesa-vulkan-drivers provides the "
        "lavapipe CPU device)");
  }

  const std::string wanted = lowercase(options.device_name);
  std::string report;  // why each candidate was passed over
  int best_rank = -1;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    const std::string line = std::string("  ") + p.deviceName + " (" + type_name(p.deviceType) + ")";
    if (!wanted.empty() && lowercase(p.deviceName).find(wanted) == std::string::npos) {
      report += line + ": name does not contain \"" + options.device_name + "\"\n";
      continue;
    }
    uint32_t family = 0;
    const std::vector<std::string> reasons = disqualifications(d, options.presentation, family);
    if (!reasons.empty()) {
      report += line + ": lacks\n";
      for (const std::string& r : reasons) report += "      - " + r + "\n";
      continue;
    }
    report += line + ": suitable\n";
    if (type_rank(p.deviceType) > best_rank) {
      best_rank = type_rank(p.deviceType);
      physical_device_ = d;
      properties_ = p;
      queue_family_ = family;
    }
  }
  if (physical_device_ == VK_NULL_HANDLE) {
    throw VulkanError("no suitable Vulkan device" +
                      (wanted.empty() ? std::string() : " matching \"" + options.device_name + "\"") + ":\n" +
                      report);
  }

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  DeviceFeatures features;
  enable_required_features(features);
  DeviceFeatures supported;
  query_features(physical_device_, supported);
  optional_features_ = enable_optional_features(supported, features);
  std::vector<const char*> extensions;
  if (options.presentation) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executable_info{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
  if (options.pipeline_statistics) {
    if (has_device_extension(physical_device_, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME)) {
      extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
      executable_info.pipelineExecutableInfo = VK_TRUE;
      executable_info.pNext = features.core.pNext;
      features.core.pNext = &executable_info;
    } else {
      std::printf("shadowgraph: %s reports no pipeline statistics (no %s)\n", properties_.deviceName,
                  VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
    }
  }

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &features.core;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice");
  if (executable_info.pipelineExecutableInfo)
    pipeline_statistics_ = std::make_unique<PipelineStatisticsLog>(device_);
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pool_info.queueFamilyIndex = queue_family_;
  check(vkCreateCommandPool(device_, &pool_info, nullptr, &one_time_pool_), "vkCreateCommandPool");

  allocator_ = std::make_unique<GpuAllocator>(physical_device_, device_);
}

void VulkanContext::begin_label(VkCommandBuffer cmd, const char* name) const {
  if (!cmd_begin_label_) return;
  VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  label.pLabelName = name;
  cmd_begin_label_(cmd, &label);
}

void VulkanContext::end_label(VkCommandBuffer cmd) const {
  if (cmd_end_label_) cmd_end_label_(cmd);
}

void VulkanContext::set_name(VkObjectType type, uint64_t handle, const char* name) const {
  if (!set_object_name_) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name;
  set_object_name_(device_, &info);
}

void VulkanContext::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = one_time_pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(cmd, &begin);
  record(cmd);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");

  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  check(vkCreateFence(device_, &fence_info, nullptr, &fence), "vkCreateFence");
  VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmd_info.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmd_info;
  const VkResult result = vkQueueSubmit2(queue_, 1, &submit, fence);
  if (result == VK_SUCCESS) vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX);
  vkDestroyFence(device_, fence, nullptr);
  vkFreeCommandBuffers(device_, one_time_pool_, 1, &cmd);
  check(result, "vkQueueSubmit2");
}

}  // namespace sg::vk
