// SPDX-License-Identifier: MIT
#include "rendergraph/core/aliasing.h"

#include <gtest/gtest.h>

#include "test_graphs.h"

namespace sg::rg {
namespace {

using namespace sg::rg::testing;

TEST(PlanAliasing, ResourcesWithDisjointLifetimesShareMemory) {
  const std::vector<AliasingRequest> requests{
      {ResourceKind::image, 1024, 256, {0, 1}},
      {ResourceKind::image, 1024, 256, {2, 3}},
      {ResourceKind::image, 512, 256, {1, 2}},  // alive beside both: needs its own bytes
  };
  const AliasingPlan plan = plan_aliasing(requests);

  ASSERT_EQ(plan.heaps.size(), 2u);
  EXPECT_EQ(plan.placements[0].heap, plan.placements[1].heap);
  EXPECT_EQ(plan.placements[0].offset, 0u);
  EXPECT_EQ(plan.placements[1].offset, 0u);
  EXPECT_EQ(plan.placements[1].previous_occupants, (std::vector<std::uint32_t>{0}));
  EXPECT_NE(plan.placements[2].heap, plan.placements[0].heap);
  EXPECT_EQ(plan.heaps[0].size + plan.heaps[1].size, 1024u + 512u);
}

TEST(PlanAliasing, SmallResourcesPackBesideEachOtherInALargerOnesHeap) {
  const std::vector<AliasingRequest> requests{
      {ResourceKind::image, 4096, 1024, {0, 0}},
      {ResourceKind::image, 1000, 1024, {1, 2}},
      {ResourceKind::image, 1000, 1024, {1, 2}},
  };
  const AliasingPlan plan = plan_aliasing(requests);

  ASSERT_EQ(plan.heaps.size(), 1u);
  EXPECT_EQ(plan.placements[1].offset, 0u);
  EXPECT_EQ(plan.placements[2].offset, 1024u) << "aligned past its neighbour";
  EXPECT_EQ(plan.placements[2].previous_occupants, (std::vector<std::uint32_t>{0}));
}

TEST(PlanAliasing, ImagesAndBuffersNeverShareAHeap) {
  const std::vector<AliasingRequest> requests{
      {ResourceKind::image, 1024, 256, {0, 0}},
      {ResourceKind::buffer, 1024, 256, {1, 1}},
  };
  const AliasingPlan plan = plan_aliasing(requests);
  ASSERT_EQ(plan.heaps.size(), 2u);
  EXPECT_EQ(plan.heaps[plan.placements[1].heap].kind, ResourceKind::buffer);
}

TEST(EstimateRequest, SumsMipsAndLayersAndAlignsImagesTo64KiB) {
  CompiledResource image;
  image.image = {1024, 1024, Format::rgba8_unorm, 2, 2};
  const std::uint64_t texels = 1024 * 1024 + 512 * 512;
  EXPECT_EQ(estimate_request(image).size, texels * 4 * 2);
  EXPECT_EQ(estimate_request(image).alignment, 65536u);

  CompiledResource buffer;
  buffer.kind = ResourceKind::buffer;
  buffer.buffer.size = 1000;
  EXPECT_EQ(estimate_request(buffer).size, 1024u);
}

// Two post-processing intermediates used one after the other: the second reuses the first's
// memory, reports the bytes saved, and its first barrier waits for the first's last reads.
TEST(CompiledAliasing, SequentialIntermediatesShareOneHeap) {
  RenderGraph graph;
  ImageHandle swapchain = graph.import_image("swapchain", screen_color_desc, acquired, presentable);
  ImageHandle a{};
  ImageHandle b_image{};
  graph.add_pass("draw a", QueueType::graphics, [&](PassBuilder& b) {
    a = b.write(b.create_image("a", screen_color_desc), Usage::color_attachment);
  });
  graph.add_pass("compose a", QueueType::graphics, [&](PassBuilder& b) {
    b.read(a, Usage::sampled_fragment);
    swapchain = b.write(swapchain, Usage::color_attachment);
  });
  graph.add_pass("draw b", QueueType::graphics, [&](PassBuilder& b) {
    b_image = b.write(b.create_image("b", screen_color_desc), Usage::color_attachment);
  });
  graph.add_pass("compose b", QueueType::graphics, [&](PassBuilder& b) {
    b.read(b_image, Usage::sampled_fragment);
    swapchain = b.write(swapchain, Usage::color_attachment);
  });
  const auto plan = compile_ok(graph);

  const CompiledResource& first = plan->resources[a.index];
  const CompiledResource& second = plan->resources[b_image.index];
  EXPECT_EQ(first.lifetime, (Lifetime{0, 1}));
  EXPECT_EQ(second.lifetime, (Lifetime{2, 3}));
  EXPECT_EQ(first.image_usage, ImageUsage::color_attachment | ImageUsage::sampled);
  ASSERT_TRUE(first.placement && second.placement);
  EXPECT_EQ(first.placement->heap, second.placement->heap);
  EXPECT_EQ(second.placement->previous_occupants, (std::vector<std::uint32_t>{a.index}));
  EXPECT_FALSE(plan->resources[swapchain.index].placement) << "imported resources are not the graph's memory";

  const std::uint64_t one = estimate_request(first).size;
  EXPECT_EQ(plan->memory.unaliased_bytes, 2 * one);
  EXPECT_EQ(plan->memory.aliased_bytes, one);
  EXPECT_EQ(plan->memory.saved_bytes(), one);

  const ImageBarrier& takeover = plan->passes[2].barriers.images.at(0);
  EXPECT_EQ(takeover.resource, b_image.index);
  EXPECT_EQ(takeover.dependency.src_stages, PipelineStage::fragment_shader);
  EXPECT_EQ(takeover.dependency.old_layout, ImageLayout::undefined);
}

}  // namespace
}  // namespace sg::rg
