// SPDX-License-Identifier: MIT
#include "rendergraph/device/pipeline_statistics.h"

#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {
namespace {

double statistic_value(const VkPipelineExecutableStatisticKHR& statistic) {
  switch (statistic.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR: return statistic.value.b32 ? 1.0 : 0.0;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR: return static_cast<double>(statistic.value.i64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR: return static_cast<double>(statistic.value.u64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR: return statistic.value.f64;
    default: return 0.0;
  }
}

}  // namespace

PipelineStatisticsLog::PipelineStatisticsLog(VkDevice device)
    : device_(device),
      get_properties_(reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
          vkGetDeviceProcAddr(device, "vkGetPipelineExecutablePropertiesKHR"))),
      get_statistics_(reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
          vkGetDeviceProcAddr(device, "vkGetPipelineExecutableStatisticsKHR"))) {}

void PipelineStatisticsLog::capture(VkPipeline pipeline, std::string_view name) {
  VkPipelineInfoKHR pipeline_info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
  pipeline_info.pipeline = pipeline;
  uint32_t count = 0;
  check(get_properties_(device_, &pipeline_info, &count, nullptr), "vkGetPipelineExecutablePropertiesKHR");
  std::vector<VkPipelineExecutablePropertiesKHR> properties(
      count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
  check(get_properties_(device_, &pipeline_info, &count, properties.data()),
        "vkGetPipelineExecutablePropertiesKHR");

  std::vector<PipelineExecutable> captured;
  for (uint32_t index = 0; index < count; ++index) {
    VkPipelineExecutableInfoKHR executable_info{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
    executable_info.pipeline = pipeline;
    executable_info.executableIndex = index;
    uint32_t statistic_count = 0;
    check(get_statistics_(device_, &executable_info, &statistic_count, nullptr),
          "vkGetPipelineExecutableStatisticsKHR");
    std::vector<VkPipelineExecutableStatisticKHR> statistics(
        statistic_count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
    check(get_statistics_(device_, &executable_info, &statistic_count, statistics.data()),
          "vkGetPipelineExecutableStatisticsKHR");
    PipelineExecutable executable{std::string(name), properties[index].name, {}};
    for (const VkPipelineExecutableStatisticKHR& statistic : statistics) {
      executable.statistics.push_back({statistic.name, statistic_value(statistic)});
    }
    captured.push_back(std::move(executable));
  }
  const std::lock_guard lock(mutex_);
  executables_.insert(executables_.end(), captured.begin(), captured.end());
}

std::vector<PipelineExecutable> PipelineStatisticsLog::executables() const {
  const std::lock_guard lock(mutex_);
  return executables_;
}

}  // namespace sg::vk
