// SPDX-License-Identifier: MIT
// Compute pipelines built on a thread of their own: each asked for once, each built with its own
// constants, found once built.
#include <cstdint>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "device_test_shaders/write_constant.comp.spv.h"
#include "rendergraph/device/background_pipelines.h"
#include "rendergraph/device/barriers.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/resources.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

class BackgroundPipelinesTest : public GpuTest {
 protected:
  vk::PipelineLayout layout{context.device(),
                            {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT}}};
  vk::Buffer out{context, {4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::readback, "written"}};

  vk::ComputePipelineDesc writing(uint32_t value) const {
    return {write_constant_comp, {value}, layout.get(), "write " + std::to_string(value)};
  }

  // What `pipeline` writes.
  uint32_t run(VkPipeline pipeline) {
    vk::DescriptorSets sets = layout.allocate_sets(1);
    layout.write(sets.sets[0]).buffer(0, out.handle()).update();
    context.submit_and_wait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
      layout.bind_compute(cmd, sets.sets[0]);
      vkCmdDispatch(cmd, 1, 1, 1);
      vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                         VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    uint32_t written = 0;
    std::memcpy(&written, out.mapped(), sizeof(written));
    return written;
  }
};

TEST_F(BackgroundPipelinesTest, EachKeyIsBuiltOnceWithItsOwnDescription) {
  vk::BackgroundPipelines builds(context);
  EXPECT_EQ(builds.find(1), VK_NULL_HANDLE) << "never asked for";
  builds.request(1, writing(7));
  builds.request(2, writing(9));
  builds.request(1, writing(8));  // asked for before: ignored
  EXPECT_TRUE(builds.asked(1));
  EXPECT_FALSE(builds.asked(3));
  EXPECT_LE(builds.pending(), 2u);
  builds.wait();
  EXPECT_EQ(builds.pending(), 0u);
  const VkPipeline first = builds.find(1);
  const VkPipeline second = builds.find(2);
  ASSERT_NE(first, VK_NULL_HANDLE);
  ASSERT_NE(second, VK_NULL_HANDLE);
  EXPECT_EQ(run(first), 7u);
  EXPECT_EQ(run(second), 9u);
  builds.request(1, writing(8));
  EXPECT_EQ(builds.pending(), 0u) << "built already";
  EXPECT_EQ(builds.find(1), first);
}

// Destroyed while builds wait: the one in progress finishes, the others are dropped.
TEST_F(BackgroundPipelinesTest, DestroyedWithBuildsPending) {
  {
    vk::BackgroundPipelines builds(context);
    for (uint32_t key = 0; key < 16; ++key) builds.request(key, writing(key));
  }
  EXPECT_EQ(context.validation_errors(), 0u);
}

}  // namespace
}  // namespace sg::test
