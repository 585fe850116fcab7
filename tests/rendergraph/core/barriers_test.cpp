// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "test_graphs.h"

namespace sg::rg {
namespace {

using namespace sg::rg::testing;

const ImageBarrier& only_image_barrier(const BarrierBatch& batch) {
  EXPECT_EQ(batch.images.size(), 1u);
  EXPECT_TRUE(batch.buffers.empty());
  if (batch.images.empty()) throw std::runtime_error("no image barrier");
  return batch.images.front();
}

TEST(Barriers, TransientDepthIsDiscardedThenTransitionedForSampling) {
  RenderGraph graph;
  ImageHandle swapchain = graph.import_image("swapchain", screen_color_desc, acquired, presentable);
  ImageHandle depth{};
  graph.add_pass("depth prepass", QueueType::graphics, [&](PassBuilder& b) {
    depth = b.write(b.create_image("depth", {1280, 720, Format::d32_sfloat}), Usage::depth_attachment);
  });
  graph.add_pass("lighting", QueueType::graphics, [&](PassBuilder& b) {
    b.read(depth, Usage::sampled_fragment);
    swapchain = b.write(swapchain, Usage::color_attachment);
  });
  const auto plan = compile_ok(graph);

  const ImageBarrier& discard = only_image_barrier(plan->passes[0].barriers);
  EXPECT_EQ(discard.resource, depth.index);
  EXPECT_EQ(discard.range, (SubresourceRange{0, 1, 0, 1}));
  EXPECT_EQ(discard.dependency, (Dependency{PipelineStage::none, Access::none, depth_tests, depth_read_write,
                                            ImageLayout::undefined, ImageLayout::attachment_optimal}));

  const BarrierBatch& before_lighting = plan->passes[1].barriers;
  ASSERT_EQ(before_lighting.images.size(), 2u) << "depth and swapchain share one batch";
  EXPECT_EQ(before_lighting.images[0].dependency,
            (Dependency{depth_tests, Access::depth_stencil_attachment_write, PipelineStage::fragment_shader,
                        Access::shader_sampled_read, ImageLayout::attachment_optimal,
                        ImageLayout::read_only_optimal}));
  EXPECT_EQ(before_lighting.images[1].resource, swapchain.index);
  EXPECT_EQ(before_lighting.images[1].dependency,
            (Dependency{PipelineStage::color_attachment_output, Access::none,
                        PipelineStage::color_attachment_output, color_read_write, ImageLayout::undefined,
                        ImageLayout::attachment_optimal}));

  const ImageBarrier& present = only_image_barrier(plan->final_barriers);
  EXPECT_EQ(present.dependency, (Dependency{PipelineStage::color_attachment_output,
                                            Access::color_attachment_write, PipelineStage::none, Access::none,
                                            ImageLayout::attachment_optimal, ImageLayout::present_src}));
}

// Rendering face 3 of cube 1 in a cube-map array, then sampling all of cube 1: only layer 9
// changes layout, twice; the other faces stay readable and get no barrier.
class CubeFace : public ::testing::Test {
 protected:
  void build(const std::vector<RangeState>& initial) {
    ImageHandle cubes = graph.import_image("point shadows", cube_array_desc, initial, sampled_in_fragment);
    ImageHandle swapchain = graph.import_image("swapchain", screen_color_desc, acquired, presentable);
    graph.add_pass("light 1 face 3", QueueType::graphics, [&](PassBuilder& b) {
      cubes = b.write(cubes, Usage::depth_attachment, SubresourceRange::cube_face(1, 3));
    });
    graph.add_pass("lighting", QueueType::graphics, [&](PassBuilder& b) {
      b.read(cubes, Usage::sampled_fragment, SubresourceRange::cube(1));
      swapchain = b.write(swapchain, Usage::color_attachment);
    });
  }

  RenderGraph graph;
};

TEST_F(CubeFace, OnlyTheRenderedFaceIsTransitioned) {
  build({{SubresourceRange::all(), sampled_in_fragment}});
  const auto plan = compile_ok(graph);

  const ImageBarrier& to_attachment = only_image_barrier(plan->passes[0].barriers);
  EXPECT_EQ(to_attachment.range, (SubresourceRange{0, 1, 9, 1}));
  EXPECT_EQ(to_attachment.dependency,
            (Dependency{PipelineStage::fragment_shader, Access::none, depth_tests, depth_read_write,
                        ImageLayout::read_only_optimal, ImageLayout::attachment_optimal}));

  const BarrierBatch& before_lighting = plan->passes[1].barriers;
  ASSERT_EQ(before_lighting.images.size(), 2u);
  const ImageBarrier& to_sampled = before_lighting.images[0];
  EXPECT_EQ(to_sampled.range, (SubresourceRange{0, 1, 9, 1}));
  EXPECT_EQ(to_sampled.dependency.src_access, Access::depth_stencil_attachment_write);
  EXPECT_EQ(to_sampled.dependency.new_layout, ImageLayout::read_only_optimal);

  EXPECT_EQ(plan->final_barriers.images.size(), 1u)
      << "only the swapchain; the cubes already are in their final state";
  ASSERT_EQ(plan->exported_states.size(), 2u);
  EXPECT_EQ(plan->exported_states[0].states,
            (std::vector<RangeState>{{SubresourceRange{0, 1, 0, 24}, sampled_in_fragment}}));
}

TEST_F(CubeFace, FacesWithDifferentHistoriesGetSeparateBarriers) {
  // Cube 1 was never rendered: faces 0-5 start undefined, so sampling them needs transitions;
  // face 3 comes from the attachment layout and the others from undefined.
  build({{SubresourceRange::all(), sampled_in_fragment}, {SubresourceRange::cube(1), {}}});
  const auto plan = compile_ok(graph);

  std::vector<SubresourceRange> ranges;
  for (const ImageBarrier& barrier : plan->passes[1].barriers.images) {
    if (barrier.resource == 0) ranges.push_back(barrier.range);
  }
  EXPECT_EQ(ranges, (std::vector<SubresourceRange>{{0, 1, 6, 3}, {0, 1, 9, 1}, {0, 1, 10, 2}}));
  EXPECT_EQ(plan->passes[0].barriers.images[0].dependency.old_layout, ImageLayout::undefined);
}

TEST(Barriers, ShadowPassesPerLayerMergeIntoOneBarrierBeforeLighting) {
  RenderGraph graph;
  ImageHandle atlas = graph.import_image("atlas", shadow_atlas_desc, ResourceState{}, sampled_in_fragment);
  for (std::uint32_t layer = 0; layer < shadow_atlas_desc.layers; ++layer) {
    graph.add_pass("spot " + std::to_string(layer), QueueType::graphics, [&](PassBuilder& b) {
      atlas = b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(layer));
    });
  }
  graph.add_pass("lighting", QueueType::graphics, [&](PassBuilder& b) {
    b.read(atlas, Usage::sampled_fragment);
    b.mark_side_effects();
  });
  const auto plan = compile_ok(graph);

  ASSERT_EQ(plan->passes.size(), 17u);
  EXPECT_EQ(only_image_barrier(plan->passes[5].barriers).range, (SubresourceRange{0, 1, 5, 1}));
  const ImageBarrier& merged = only_image_barrier(plan->passes[16].barriers);
  EXPECT_EQ(merged.range, (SubresourceRange{0, 1, 0, 16}));
  EXPECT_EQ(merged.dependency.old_layout, ImageLayout::attachment_optimal);
  EXPECT_TRUE(plan->final_barriers.empty());
}

TEST(Barriers, ReadsInTheSameLayoutAndStageNeedNoBarrierAndANewStageOnlyVisibility) {
  RenderGraph graph;
  ImageHandle depth{};
  graph.add_pass("depth", QueueType::graphics, [&](PassBuilder& b) {
    depth = b.write(b.create_image("depth", {1280, 720, Format::d32_sfloat}), Usage::depth_attachment);
  });
  for (const char* name : {"fog", "decals"}) {
    graph.add_pass(name, QueueType::graphics, [&](PassBuilder& b) {
      b.read(depth, Usage::sampled_fragment);
      b.mark_side_effects();
    });
  }
  graph.add_pass("ssao", QueueType::compute, [&](PassBuilder& b) {
    b.read(depth, Usage::sampled_compute);
    b.mark_side_effects();
  });
  const auto plan = compile_ok(graph);

  EXPECT_EQ(only_image_barrier(plan->passes[1].barriers).dependency.new_layout,
            ImageLayout::read_only_optimal);
  EXPECT_TRUE(plan->passes[2].barriers.empty());
  EXPECT_EQ(only_image_barrier(plan->passes[3].barriers).dependency,
            (Dependency{PipelineStage::fragment_shader, Access::none, PipelineStage::compute_shader,
                        Access::shader_sampled_read, ImageLayout::read_only_optimal,
                        ImageLayout::read_only_optimal}));
}

TEST(Barriers, CompatibleReadsInOnePassShareOneBarrier) {
  RenderGraph graph;
  ImageHandle depth{};
  graph.add_pass("depth", QueueType::graphics, [&](PassBuilder& b) {
    depth = b.write(b.create_image("depth", {1280, 720, Format::d32_sfloat}), Usage::depth_attachment);
  });
  graph.add_pass("soft particles", QueueType::graphics, [&](PassBuilder& b) {
    b.read(depth, Usage::depth_attachment);
    b.read(depth, Usage::sampled_fragment);
    b.mark_side_effects();
  });
  const auto plan = compile_ok(graph);

  const ImageBarrier& barrier = only_image_barrier(plan->passes[1].barriers);
  EXPECT_EQ(barrier.dependency.dst_stages, depth_tests | PipelineStage::fragment_shader);
  EXPECT_EQ(barrier.dependency.dst_access,
            Access::depth_stencil_attachment_read | Access::shader_sampled_read);
}

TEST(Barriers, DownsamplingReadsOneMipAndWritesTheNext) {
  RenderGraph graph;
  ImageHandle bloom{};
  graph.add_pass("bright pass", QueueType::compute, [&](PassBuilder& b) {
    bloom = b.create_image("bloom", {1024, 1024, Format::rgba16_sfloat, 1, 3});
    bloom = b.write(bloom, Usage::storage_compute, SubresourceRange::mip(0));
  });
  graph.add_pass("downsample 1", QueueType::compute, [&](PassBuilder& b) {
    b.read(bloom, Usage::sampled_compute, SubresourceRange::mip(0));
    bloom = b.write(bloom, Usage::storage_compute, SubresourceRange::mip(1));
    b.mark_side_effects();
  });
  const auto plan = compile_ok(graph);

  EXPECT_EQ(only_image_barrier(plan->passes[0].barriers).range, (SubresourceRange{0, 1, 0, 1}));
  const auto& images = plan->passes[1].barriers.images;
  ASSERT_EQ(images.size(), 2u);
  EXPECT_EQ(images[0].range, (SubresourceRange{0, 1, 0, 1}));
  EXPECT_EQ(images[0].dependency.old_layout, ImageLayout::general);
  EXPECT_EQ(images[0].dependency.src_access, Access::shader_storage_write);
  EXPECT_EQ(images[1].range, (SubresourceRange{1, 1, 0, 1}));
  EXPECT_EQ(images[1].dependency.old_layout, ImageLayout::undefined);
}

TEST(Barriers, BuffersGetBufferBarriersWithoutLayouts) {
  RenderGraph graph;
  BufferHandle draws{};
  graph.add_pass("cull", QueueType::compute, [&](PassBuilder& b) {
    draws = b.write(b.create_buffer("draw commands", {64 * 1024}), Usage::storage_compute);
  });
  graph.add_pass("draw", QueueType::graphics, [&](PassBuilder& b) {
    b.read(draws, Usage::indirect);
    b.mark_side_effects();
  });
  const auto plan = compile_ok(graph);

  EXPECT_TRUE(plan->passes[0].barriers.empty()) << "nothing to wait for before a fresh buffer's first write";
  ASSERT_EQ(plan->passes[1].barriers.buffers.size(), 1u);
  EXPECT_EQ(
      plan->passes[1].barriers.buffers[0].dependency,
      (Dependency{PipelineStage::compute_shader, Access::shader_storage_write, PipelineStage::draw_indirect,
                  Access::indirect_command_read, ImageLayout::undefined, ImageLayout::undefined}));
  EXPECT_EQ(plan->resources[draws.index].buffer_usage, BufferUsage::storage | BufferUsage::indirect);
}

TEST(Barriers, ExportedStatesStartTheNextFrameWhereThisOneEnded) {
  const auto frame = [](const std::vector<RangeState>& initial) {
    RenderGraph graph;
    ImageHandle cubes = graph.import_image("cubes", cube_array_desc, initial);
    graph.add_pass("sample cube 0", QueueType::compute, [&](PassBuilder& b) {
      b.read(cubes, Usage::sampled_compute, SubresourceRange::cube(0));
      b.mark_side_effects();
    });
    return compile_ok(graph);
  };
  const auto first = frame({{SubresourceRange::all(), sampled_in_fragment}});
  ASSERT_EQ(first->passes[0].barriers.images.size(), 1u) << "fragment -> compute visibility";

  const std::vector<RangeState> exported = first->exported_states[0].states;
  const ResourceState sampled_anywhere{PipelineStage::fragment_shader | PipelineStage::compute_shader,
                                       Access::shader_sampled_read, ImageLayout::read_only_optimal};
  EXPECT_EQ(exported, (std::vector<RangeState>{{SubresourceRange{0, 1, 0, 6}, sampled_anywhere},
                                               {SubresourceRange{0, 1, 6, 18}, sampled_in_fragment}}));
  const auto second = frame(exported);
  EXPECT_TRUE(second->passes[0].barriers.empty());
}

}  // namespace
}  // namespace sg::rg
