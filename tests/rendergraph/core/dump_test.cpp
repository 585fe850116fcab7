// SPDX-License-Identifier: MIT
#include "rendergraph/core/dump.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_graphs.h"

namespace sg::rg {
namespace {

using namespace sg::rg::testing;

// A shadow pass, a culled debug pass, post intermediates of which "sharp" reuses "hdr"'s memory,
// and the swapchain.
class Dumps : public ::testing::Test {
 protected:
  Dumps() {
    ImageHandle atlas = graph.import_image("atlas", shadow_atlas_desc, ResourceState{}, sampled_in_fragment);
    ImageHandle swapchain = graph.import_image("swapchain", screen_color_desc, acquired, presentable);
    ImageHandle hdr{};
    ImageHandle bloom{};
    ImageHandle sharp{};
    graph.add_pass("spot \"key\"", QueueType::graphics, [&](PassBuilder& b) {
      atlas = b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(2));
    });
    graph.add_pass("lighting", QueueType::graphics, [&](PassBuilder& b) {
      b.read(atlas, Usage::sampled_fragment);
      hdr = b.write(b.create_image("hdr", screen_color_desc), Usage::color_attachment);
    });
    graph.add_pass("debug", QueueType::graphics, [&](PassBuilder& b) {
      b.read(hdr, Usage::sampled_fragment);
      (void)b.write(b.create_image("debug", screen_color_desc), Usage::color_attachment);
    });
    graph.add_pass("bloom", QueueType::compute, [&](PassBuilder& b) {
      b.read(hdr, Usage::sampled_compute);
      bloom = b.write(b.create_image("bloom", screen_color_desc), Usage::storage_compute);
    });
    graph.add_pass("sharpen", QueueType::graphics, [&](PassBuilder& b) {
      b.read(bloom, Usage::sampled_fragment);
      sharp = b.write(b.create_image("sharp", screen_color_desc), Usage::color_attachment);
    });
    graph.add_pass("tonemap", QueueType::graphics, [&](PassBuilder& b) {
      b.read(sharp, Usage::sampled_fragment);
      swapchain = b.write(swapchain, Usage::color_attachment);
    });
    plan = compile_ok(graph);
  }

  RenderGraph graph;
  std::shared_ptr<const CompiledPlan> plan;
};

TEST_F(Dumps, DotShowsPassesVersionsUsagesAndGreysCulledPasses) {
  const std::string dot = to_dot(graph, *plan);
  EXPECT_TRUE(mentions(dot, "digraph render_graph {"));
  EXPECT_TRUE(mentions(dot, "p0 [shape=box, label=\"#0 spot \\\"key\\\"\\ngraphics\"]"));
  EXPECT_TRUE(mentions(dot, "p2 [shape=box, style=filled, fillcolor=\"#dddddd\""));
  EXPECT_TRUE(mentions(dot, "r0v1 [shape=ellipse, label=\"atlas v1\\nimported\"]"));
  EXPECT_TRUE(mentions(dot, "r1v1 [shape=ellipse, label=\"swapchain v1\\nimported\"]"));
  EXPECT_TRUE(mentions(dot, "p0 -> r0v1 [label=\"depth_attachment\\nmip 0, layer 2\"]"));
  EXPECT_TRUE(mentions(dot, "r0v1 -> p1 [label=\"sampled_fragment\"]"));
  // The atlas layer is drawn without a clear: the pass also depends on the imported contents.
  EXPECT_TRUE(mentions(dot, "r0v0 [shape=ellipse, label=\"atlas v0\\nimported\"]"));
  EXPECT_TRUE(mentions(dot, "r0v0 -> p0 [style=dashed, label=\"previous contents\"]"));
  EXPECT_EQ(dot.back(), '\n');
}

TEST_F(Dumps, JsonParsesBackWithOrderLifetimesAliasingAndBarriers) {
  const std::vector<double> milliseconds{0.25, 0.5, 0.125, 0.0625, 0.75};
  const auto json = nlohmann::json::parse(to_json(*plan, milliseconds));

  ASSERT_EQ(json["passes"].size(), 5u);
  EXPECT_EQ(json["passes"][1]["name"], "lighting");
  EXPECT_EQ(json["passes"][1]["order"], 1);
  EXPECT_EQ(json["passes"][1]["milliseconds"], 0.5);
  EXPECT_EQ(json["passes"][2]["queue"], "compute");
  EXPECT_EQ(json["culled"][0]["name"], "debug");

  const auto& first_barrier = json["passes"][0]["barriers"]["images"][0];
  EXPECT_EQ(first_barrier["resource"], "atlas");
  EXPECT_EQ(first_barrier["range"]["base_layer"], 2);
  EXPECT_EQ(first_barrier["old_layout"], "UNDEFINED");
  EXPECT_EQ(first_barrier["dst_stages"], "EARLY_FRAGMENT_TESTS|LATE_FRAGMENT_TESTS");

  const auto& resources = json["resources"];
  EXPECT_EQ(resources[2]["name"], "hdr");
  EXPECT_EQ(resources[2]["lifetime"]["first"], 1);
  EXPECT_EQ(resources[2]["lifetime"]["last"], 2);
  EXPECT_TRUE(resources[3]["lifetime"].is_null()) << "debug was culled";
  EXPECT_EQ(resources[5]["name"], "sharp");
  EXPECT_EQ(resources[5]["placement"]["heap"], resources[2]["placement"]["heap"]);
  EXPECT_EQ(resources[5]["placement"]["offset"], 0);
  EXPECT_EQ(resources[5]["placement"]["reuses_memory_of"], nlohmann::json::array({"hdr"}));
  EXPECT_NE(resources[4]["placement"]["heap"], resources[2]["placement"]["heap"]) << "bloom lives beside hdr";
  EXPECT_EQ(json["heaps"].size(), 2u);
  EXPECT_EQ(json["memory"]["saved_bytes"].get<std::uint64_t>(), plan->memory.saved_bytes());
  EXPECT_EQ(json["final_barriers"]["images"][0]["new_layout"], "PRESENT_SRC");
  EXPECT_EQ(json["exported_states"][0]["states"][0]["layout"], "READ_ONLY_OPTIMAL");
}

TEST_F(Dumps, JsonTimingsAreNullUntilTheExecutorMeasuresThem) {
  const auto json = nlohmann::json::parse(to_json(*plan));
  for (const auto& pass : json["passes"]) EXPECT_TRUE(pass["milliseconds"].is_null());
}

}  // namespace
}  // namespace sg::rg
