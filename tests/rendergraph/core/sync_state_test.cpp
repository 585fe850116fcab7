// SPDX-License-Identifier: MIT
#include "rendergraph/core/sync_state.h"

#include <gtest/gtest.h>

#include "test_graphs.h"

namespace sg::rg {
namespace {

using namespace sg::rg::testing;

constexpr ResourceState depth_write{depth_tests, depth_read_write, ImageLayout::attachment_optimal};
constexpr ResourceState compute_sample{PipelineStage::compute_shader, Access::shader_sampled_read,
                                       ImageLayout::read_only_optimal};

TEST(Advance, FirstWriteOfAFreshImageDiscardsFromUndefinedWithoutWaiting) {
  SyncState state;
  const auto dependency = advance(state, depth_write);
  ASSERT_TRUE(dependency);
  EXPECT_EQ(dependency->src_stages, PipelineStage::none);
  EXPECT_EQ(dependency->src_access, Access::none);
  EXPECT_EQ(dependency->old_layout, ImageLayout::undefined);
  EXPECT_EQ(dependency->new_layout, ImageLayout::attachment_optimal);
  EXPECT_EQ(dependency->dst_access, depth_read_write);
}

TEST(Advance, FirstWriteOfAFreshBufferNeedsNoBarrier) {
  SyncState state;
  EXPECT_FALSE(
      advance(state, {PipelineStage::compute_shader, Access::shader_storage_write, ImageLayout::undefined}));
}

TEST(Advance, ReadAfterWriteMakesTheWriteAvailableAndTransitions) {
  SyncState state;
  advance(state, depth_write);
  const auto dependency = advance(state, sampled_in_fragment);
  ASSERT_TRUE(dependency);
  EXPECT_EQ(dependency->src_stages, depth_tests);
  EXPECT_EQ(dependency->src_access, Access::depth_stencil_attachment_write);
  EXPECT_EQ(dependency->dst_stages, PipelineStage::fragment_shader);
  EXPECT_EQ(dependency->dst_access, Access::shader_sampled_read);
  EXPECT_EQ(dependency->old_layout, ImageLayout::attachment_optimal);
  EXPECT_EQ(dependency->new_layout, ImageLayout::read_only_optimal);
}

TEST(Advance, ReadAfterReadInTheSameLayoutAndStageNeedsNoBarrier) {
  SyncState state;
  advance(state, depth_write);
  advance(state, sampled_in_fragment);
  EXPECT_FALSE(advance(state, sampled_in_fragment));
}

TEST(Advance, ReadInANewStageOnlyNeedsVisibilityChainedAfterTheTransition) {
  SyncState state;
  advance(state, depth_write);
  advance(state, sampled_in_fragment);
  const auto dependency = advance(state, compute_sample);
  ASSERT_TRUE(dependency);
  EXPECT_EQ(dependency->src_stages, PipelineStage::fragment_shader);
  EXPECT_EQ(dependency->src_access, Access::none);
  EXPECT_EQ(dependency->old_layout, dependency->new_layout);
}

TEST(Advance, WriteAfterReadWaitsForTheReadersWithoutFlushing) {
  SyncState state = imported_state(sampled_in_fragment);
  const auto dependency = advance(state, depth_write);
  ASSERT_TRUE(dependency);
  EXPECT_EQ(dependency->src_stages, PipelineStage::fragment_shader);
  EXPECT_EQ(dependency->src_access, Access::none);
  EXPECT_EQ(dependency->old_layout, ImageLayout::read_only_optimal);
}

TEST(ImportedState, RoundTripsThroughExport) {
  SyncState state;
  advance(state, depth_write);
  advance(state, sampled_in_fragment);
  EXPECT_EQ(exported_state(state), sampled_in_fragment);
  EXPECT_EQ(exported_state(imported_state(sampled_in_fragment)), sampled_in_fragment);
}

TEST(ReusedMemoryState, WaitsForThePreviousOwnerButKeepsNothing) {
  SyncState previous;
  advance(previous, depth_write);
  advance(previous, sampled_in_fragment);
  SyncState state = reused_memory_state(previous);
  EXPECT_EQ(state.layout, ImageLayout::undefined);
  const auto dependency = advance(
      state, {PipelineStage::color_attachment_output, color_read_write, ImageLayout::attachment_optimal});
  ASSERT_TRUE(dependency);
  EXPECT_EQ(dependency->src_stages, PipelineStage::fragment_shader);
  EXPECT_EQ(dependency->old_layout, ImageLayout::undefined);
}

}  // namespace
}  // namespace sg::rg
