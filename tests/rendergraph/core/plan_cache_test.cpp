// SPDX-License-Identifier: MIT
#include "rendergraph/core/plan_cache.h"

#include <gtest/gtest.h>

#include "test_graphs.h"

namespace sg::rg {
namespace {

using namespace sg::rg::testing;

// One frame: `lights` shadow passes into the atlas, then lighting; `executed` counts the
// lighting pass's callback so the test can tell which frame's callback runs.
RenderGraph frame(std::uint32_t lights, ResourceState atlas_initial, int* executed = nullptr) {
  RenderGraph graph;
  ImageHandle atlas = graph.import_image("atlas", shadow_atlas_desc, atlas_initial, sampled_in_fragment);
  for (std::uint32_t light = 0; light < lights; ++light) {
    graph.add_pass("spot", QueueType::graphics, [&](PassBuilder& b) {
      atlas = b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(light));
    });
  }
  graph.add_pass(
      "lighting", QueueType::graphics,
      [&](PassBuilder& b) {
        b.read(atlas, Usage::sampled_fragment);
        b.mark_side_effects();
      },
      [executed](PassContext&) { ++*executed; });
  return graph;
}

TEST(GraphShape, DiffersWhenAnythingCompileReadsDiffers) {
  const GraphShape base = graph_shape(frame(3, sampled_in_fragment));
  EXPECT_EQ(base, graph_shape(frame(3, sampled_in_fragment)));
  EXPECT_NE(base, graph_shape(frame(4, sampled_in_fragment)));
  EXPECT_NE(base, graph_shape(frame(3, ResourceState{})));
}

TEST(PlanCache, ReusesThePlanOfAnEquallyShapedGraph) {
  PlanCache cache;
  const CompileResult first = cache.get_or_compile(frame(3, sampled_in_fragment));
  const CompileResult second = cache.get_or_compile(frame(3, sampled_in_fragment));
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_EQ(first.plan, second.plan);
  EXPECT_EQ(cache.hits(), 1u);
  EXPECT_EQ(cache.misses(), 1u);
}

TEST(PlanCache, TheReusedPlanDrivesTheNewGraphsCallbacks) {
  PlanCache cache;
  int old_frame = 0;
  int new_frame = 0;
  (void)cache.get_or_compile(frame(2, sampled_in_fragment, &old_frame));
  const RenderGraph graph = frame(2, sampled_in_fragment, &new_frame);
  const CompileResult result = cache.get_or_compile(graph);
  ASSERT_TRUE(result.ok());

  int recorder = 0;
  PassContext context(recorder);
  graph.passes()[result.plan->passes.back().declared_index].execute(context);
  EXPECT_EQ(new_frame, 1);
  EXPECT_EQ(old_frame, 0);
}

TEST(PlanCache, KeepsTheMostRecentlyUsedShapes) {
  PlanCache cache(2);
  (void)cache.get_or_compile(frame(1, sampled_in_fragment));
  (void)cache.get_or_compile(frame(2, sampled_in_fragment));
  (void)cache.get_or_compile(frame(1, sampled_in_fragment));  // hit: 1 becomes most recent
  (void)cache.get_or_compile(frame(3, sampled_in_fragment));  // evicts 2
  (void)cache.get_or_compile(frame(1, sampled_in_fragment));
  EXPECT_EQ(cache.hits(), 2u);
  (void)cache.get_or_compile(frame(2, sampled_in_fragment));
  EXPECT_EQ(cache.misses(), 4u);
  EXPECT_EQ(cache.size(), 2u);
}

TEST(PlanCache, DoesNotKeepGraphsWithErrors) {
  PlanCache cache;
  RenderGraph graph;
  graph.add_pass("bad", QueueType::graphics,
                 [&](PassBuilder& b) { b.read(ImageHandle{}, Usage::sampled_fragment); });
  EXPECT_FALSE(cache.get_or_compile(graph).ok());
  EXPECT_EQ(cache.size(), 0u);
}

}  // namespace
}  // namespace sg::rg
