// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "test_graphs.h"

namespace sg::rg {
namespace {

using namespace sg::rg::testing;

std::vector<std::string> executed_names(const CompiledPlan& plan) {
  std::vector<std::string> names;
  for (const CompiledPass& pass : plan.passes) names.push_back(pass.name);
  return names;
}

// shadow -> lighting <- gbuffer -> debug view (unread) ; gbuffer -> readback (side effect)
class FrameSchedule : public ::testing::Test {
 protected:
  FrameSchedule() {
    ImageHandle atlas =
        graph.import_image("atlas", shadow_atlas_desc, sampled_in_fragment, sampled_in_fragment);
    ImageHandle swapchain = graph.import_image("swapchain", screen_color_desc, acquired, presentable);
    ImageHandle depth{};
    graph.add_pass("shadow", QueueType::graphics, [&](PassBuilder& b) {
      atlas = b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(0));
    });
    graph.add_pass("gbuffer", QueueType::graphics, [&](PassBuilder& b) {
      depth = b.write(b.create_image("depth", {1280, 720, Format::d32_sfloat}), Usage::depth_attachment);
    });
    graph.add_pass("debug view", QueueType::graphics, [&](PassBuilder& b) {
      b.read(depth, Usage::sampled_fragment);
      (void)b.write(b.create_image("debug", screen_color_desc), Usage::color_attachment);
    });
    graph.add_pass("lighting", QueueType::graphics, [&](PassBuilder& b) {
      b.read(atlas, Usage::sampled_fragment);
      b.read(depth, Usage::depth_attachment);
      swapchain = b.write(swapchain, Usage::color_attachment);
    });
    graph.add_pass("readback", QueueType::transfer, [&](PassBuilder& b) {
      b.read(depth, Usage::transfer);
      b.mark_side_effects();
    });
  }

  RenderGraph graph;
};

TEST_F(FrameSchedule, RunsLivePassesInDeclarationOrder) {
  const auto plan = compile_ok(graph);
  EXPECT_EQ(executed_names(*plan), (std::vector<std::string>{"shadow", "gbuffer", "lighting", "readback"}));
  EXPECT_EQ(plan->passes[3].declared_index, 4u);
  EXPECT_TRUE(plan->passes[3].side_effects);
  EXPECT_EQ(plan->passes[3].queue, QueueType::transfer);
}

TEST_F(FrameSchedule, CullsPassesWhoseOutputsNobodyReads) {
  const auto plan = compile_ok(graph);
  ASSERT_EQ(plan->culled.size(), 1u);
  EXPECT_EQ(plan->culled[0].name, "debug view");
  EXPECT_EQ(plan->culled[0].declared_index, 2u);
  EXPECT_FALSE(plan->resources[3].lifetime) << "the culled pass's output is never allocated";
  EXPECT_FALSE(plan->resources[3].placement);
}

TEST_F(FrameSchedule, DependsOnTheProducersOfWhatItReads) {
  const auto plan = compile_ok(graph);
  EXPECT_EQ(pass_named(*plan, "lighting").depends_on, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(pass_named(*plan, "readback").depends_on, (std::vector<std::uint32_t>{1}));
  EXPECT_TRUE(pass_named(*plan, "shadow").depends_on.empty());
}

TEST(Schedule, CullingFollowsChainsOfUnreadPasses) {
  RenderGraph graph;
  ImageHandle a{};
  graph.add_pass("make a", QueueType::compute, [&](PassBuilder& b) {
    a = b.write(b.create_image("a", screen_color_desc), Usage::storage_compute);
  });
  graph.add_pass("a to b", QueueType::compute, [&](PassBuilder& b) {
    b.read(a, Usage::sampled_compute);
    (void)b.write(b.create_image("b", screen_color_desc), Usage::storage_compute);
  });
  const auto plan = compile_ok(graph);
  EXPECT_TRUE(plan->passes.empty());
  EXPECT_EQ(plan->culled.size(), 2u);
}

TEST(Schedule, APartialWriteKeepsTheWriterOfTheRestAlive) {
  RenderGraph graph;
  ImageHandle cubes = graph.import_image("cubes", cube_array_desc, sampled_in_fragment, sampled_in_fragment);
  ImageHandle scratch{};
  graph.add_pass("clear scratch", QueueType::transfer, [&](PassBuilder& b) {
    scratch = b.write(b.create_image("scratch", cube_array_desc), Usage::transfer);
  });
  graph.add_pass("face 3", QueueType::graphics, [&](PassBuilder& b) {
    scratch = b.write(scratch, Usage::depth_attachment, SubresourceRange::cube_face(0, 3));
  });
  graph.add_pass("copy", QueueType::transfer, [&](PassBuilder& b) {
    b.read(scratch, Usage::transfer);
    cubes = b.write(cubes, Usage::transfer);
  });
  const auto plan = compile_ok(graph);
  EXPECT_EQ(executed_names(*plan), (std::vector<std::string>{"clear scratch", "face 3", "copy"}));
  EXPECT_EQ(pass_named(*plan, "face 3").depends_on, (std::vector<std::uint32_t>{0}));
}

TEST(Schedule, AWriterWaitsForTheReadersOfTheVersionItReplaces) {
  RenderGraph graph;
  ImageHandle history =
      graph.import_image("history", screen_color_desc, sampled_in_fragment, sampled_in_fragment);
  graph.add_pass("reproject", QueueType::graphics, [&](PassBuilder& b) {
    b.read(history, Usage::sampled_fragment);
    b.mark_side_effects();
  });
  graph.add_pass("denoise", QueueType::compute, [&](PassBuilder& b) {
    b.read(history, Usage::sampled_compute);
    b.mark_side_effects();
  });
  graph.add_pass("store history", QueueType::graphics,
                 [&](PassBuilder& b) { history = b.write(history, Usage::color_attachment); });
  const auto plan = compile_ok(graph);
  EXPECT_EQ(pass_named(*plan, "store history").depends_on, (std::vector<std::uint32_t>{0, 1}));
}

}  // namespace
}  // namespace sg::rg
