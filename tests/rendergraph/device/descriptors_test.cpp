// SPDX-License-Identifier: MIT
// The pass kit's descriptor helpers on lavapipe: writes are checked against the layout they
// name, so a binding number or type mistake is an exception at the call, not a GPU fault.
#include <stdexcept>

#include <gtest/gtest.h>

#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/resources.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

struct Constants {
  float values[4];
};

class DescriptorsTest : public GpuTest {
 protected:
  vk::PipelineLayout layout{context.device(),
                            {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT},
                             {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT},
                             {5, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}},
                            vk::push_constants<Constants>(VK_SHADER_STAGE_FRAGMENT_BIT)};
  vk::DescriptorSets sets = layout.allocate_sets(2);
  vk::Buffer buffer{context, {256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::gpu_only, "test"}};
  vk::Buffer texels{context,
                    {256, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, vk::MemoryUsage::gpu_only, "texels",
                     VK_FORMAT_R32G32B32A32_UINT}};
};

TEST_F(DescriptorsTest, TypesComeFromTheLayout) {
  EXPECT_EQ(layout.type_of(0), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  EXPECT_EQ(layout.type_of(3), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  EXPECT_THROW(layout.type_of(1), std::logic_error);
  ASSERT_EQ(sets.sets.size(), 2u);
  EXPECT_NE(sets.sets[0], sets.sets[1]);
}

TEST_F(DescriptorsTest, AWriteReturnsTheSetItUpdated) {
  EXPECT_EQ(layout.write(sets.sets[1]).buffer(0, buffer.handle()).update(), sets.sets[1]);
}

TEST_F(DescriptorsTest, ABufferMadeWithATexelFormatHasATexelViewToWrite) {
  EXPECT_EQ(buffer.texel_view(), VK_NULL_HANDLE);
  ASSERT_NE(texels.texel_view(), VK_NULL_HANDLE);
  EXPECT_EQ(layout.write(sets.sets[0]).texel_buffer(5, texels.texel_view()).update(), sets.sets[0]);
}

TEST_F(DescriptorsTest, WritesThatDoNotMatchTheLayoutAreRefused) {
  EXPECT_THROW(layout.write(sets.sets[0]).buffer(3, buffer.handle()), std::logic_error);
  EXPECT_THROW(layout.write(sets.sets[0]).buffer(5, texels.handle()), std::logic_error);
  EXPECT_THROW(layout.write(sets.sets[0]).texel_buffer(0, texels.texel_view()), std::logic_error);
  EXPECT_THROW(layout.write(sets.sets[0]).image(0, VK_NULL_HANDLE, VK_NULL_HANDLE), std::logic_error);
  EXPECT_THROW(layout.write(sets.sets[0]).buffer(7, buffer.handle()), std::logic_error);
}

}  // namespace
}  // namespace sg::test
