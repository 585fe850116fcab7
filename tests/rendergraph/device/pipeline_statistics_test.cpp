// SPDX-License-Identifier: MIT
// Pipelines' compiler statistics, when asked for: kept for every pipeline built, in the frame or on
// the background builder's thread. lavapipe (Mesa 22.3) reports none, so there the test checks
// that the device really lacks the extension and skips.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "device_test_shaders/write_constant.comp.spv.h"
#include "rendergraph/device/background_pipelines.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/pipeline.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

TEST_F(GpuTest, PipelineStatisticsAreOffUnlessAskedFor) { EXPECT_EQ(context.pipeline_statistics(), nullptr); }

TEST(PipelineStatistics, EveryPipelineBuiltReportsItsExecutables) {
  vk::ContextOptions options = validated_options();
  options.pipeline_statistics = true;
  vk::VulkanContext context(options);
  if (context.pipeline_statistics() == nullptr) {
    EXPECT_FALSE(vk::has_device_extension(context.physical_device(),
                                          VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME))
        << "the device reports them, and none were kept";
    GTEST_SKIP() << context.device_name() << " reports no pipeline statistics";
  }
  const vk::PipelineLayout layout{context.device(),
                                  {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT}}};
  const vk::UniquePipeline built_here =
      vk::create_compute_pipeline(context, {write_constant_comp, {1}, layout.get(), "built here"});
  {
    vk::BackgroundPipelines builds(context);
    builds.request(0, {write_constant_comp, {2}, layout.get(), "built in the background"});
    builds.wait();
  }
  const std::vector<vk::PipelineExecutable> executables = context.pipeline_statistics()->executables();
  for (const char* name : {"built here", "built in the background"}) {
    const auto executable = std::find_if(executables.begin(), executables.end(),
                                         [&](const vk::PipelineExecutable& e) { return e.pipeline == name; });
    ASSERT_NE(executable, executables.end()) << name;
    EXPECT_FALSE(executable->name.empty()) << name;
    EXPECT_FALSE(executable->statistics.empty()) << name;
  }
  EXPECT_EQ(context.validation_errors(), 0u);
}

}  // namespace
}  // namespace sg::test
