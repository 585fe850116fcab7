// SPDX-License-Identifier: MIT
#pragma once
// Each pipeline's compiler statistics as the driver reports them (VK_KHR_pipeline_executable_
// properties): on NVIDIA a shader's registers and instructions; lavapipe (Mesa 22.3) reports none.
// A shader's registers bound how many of its invocations a GPU keeps in flight, which is what
// hides its loads' latency, and no timer shows them: with the log on
// (ContextOptions::pipeline_statistics) every pipeline built by create_*_pipeline (pipeline.h)
// reports its executables here; the panels' (ImGui's own) does not.
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::vk {

struct PipelineStatistic {
  std::string name;  // the driver's own
  double value = 0;  // integers and booleans (0, 1) as numbers
};

// One executable of a pipeline: a compute pipeline has one, a graphics pipeline one or more a
// stage (the driver's choice).
struct PipelineExecutable {
  std::string pipeline;  // the pipeline's debug name
  std::string name;      // the driver's, e.g. "Compute Shader"
  std::vector<PipelineStatistic> statistics;
};

// The pipelines' executables in the order they were built; any thread may add to it.
class PipelineStatisticsLog {
 public:
  // For `device`, created with the extension and its pipelineExecutableInfo feature.
  explicit PipelineStatisticsLog(VkDevice device);
  // The executables of `pipeline`, built with VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR.
  void capture(VkPipeline pipeline, std::string_view name);
  std::vector<PipelineExecutable> executables() const;

 private:
  VkDevice device_;
  // Extension commands: the loader exports only the core ones.
  PFN_vkGetPipelineExecutablePropertiesKHR get_properties_;
  PFN_vkGetPipelineExecutableStatisticsKHR get_statistics_;
  mutable std::mutex mutex_;
  std::vector<PipelineExecutable> executables_;
};

}  // namespace sg::vk
