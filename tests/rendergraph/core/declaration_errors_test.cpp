// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "test_graphs.h"

namespace sg::rg {
namespace {

using namespace sg::rg::testing;

// The single error a graph reports; fails the test when there is not exactly one.
GraphError only_error(const RenderGraph& graph) {
  const CompileResult result = compile(graph);
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(result.errors.size(), 1u);
  return result.errors.empty() ? GraphError{ErrorKind::cycle, ""} : result.errors.front();
}

class DeclarationErrors : public ::testing::Test {
 protected:
  RenderGraph graph;
  ImageHandle atlas =
      graph.import_image("shadow atlas", shadow_atlas_desc, sampled_in_fragment, sampled_in_fragment);
};

TEST_F(DeclarationErrors, ReadingAnOldVersionAfterANewerWrite) {
  ImageHandle v1{};
  graph.add_pass("spot 0", QueueType::graphics, [&](PassBuilder& b) {
    v1 = b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(0));
  });
  graph.add_pass("spot 1", QueueType::graphics, [&](PassBuilder& b) {
    (void)b.write(v1, Usage::depth_attachment, SubresourceRange::layer(1));
  });
  graph.add_pass("lighting", QueueType::graphics,
                 [&](PassBuilder& b) { b.read(v1, Usage::sampled_fragment); });

  const GraphError error = only_error(graph);
  EXPECT_EQ(error.kind, ErrorKind::stale_version);
  EXPECT_TRUE(mentions(error.message, "'lighting'"));
  EXPECT_TRUE(mentions(error.message, "'shadow atlas' v1"));
  EXPECT_TRUE(mentions(error.message, "'spot 1' already wrote v2"));
}

TEST_F(DeclarationErrors, WritingAnOldVersionWouldBranchTheChain) {
  graph.add_pass("spot 0", QueueType::graphics, [&](PassBuilder& b) {
    (void)b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(0));
  });
  graph.add_pass("spot 1", QueueType::graphics, [&](PassBuilder& b) {
    (void)b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(1));
  });

  const GraphError error = only_error(graph);
  EXPECT_EQ(error.kind, ErrorKind::stale_version);
  EXPECT_TRUE(mentions(error.message, "'spot 1' writes 'shadow atlas' v0"));
}

TEST_F(DeclarationErrors, ReadingATransientNobodyWrote) {
  graph.add_pass("blur", QueueType::compute, [&](PassBuilder& b) {
    const ImageHandle moments = b.create_image("moments", {512, 512, Format::rg16_sfloat});
    b.read(moments, Usage::sampled_compute);
  });

  const GraphError error = only_error(graph);
  EXPECT_EQ(error.kind, ErrorKind::read_before_write);
  EXPECT_TRUE(mentions(error.message, "'blur' reads transient 'moments' before any pass writes it"));
}

TEST_F(DeclarationErrors, ReadingTheVersionAPassProducesItselfIsACycle) {
  graph.add_pass("feedback", QueueType::graphics, [&](PassBuilder& b) {
    const ImageHandle written = b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(0));
    b.read(written, Usage::sampled_fragment, SubresourceRange::layer(1));
  });

  const GraphError error = only_error(graph);
  EXPECT_EQ(error.kind, ErrorKind::cycle);
  EXPECT_TRUE(mentions(error.message, "'feedback' reads 'shadow atlas' v1, which it writes itself"));
}

TEST_F(DeclarationErrors, SamplingAndRenderingTheSameLayerInOnePass) {
  graph.add_pass("bad", QueueType::graphics, [&](PassBuilder& b) {
    b.read(atlas, Usage::sampled_fragment, SubresourceRange::layers(0, 4));
    (void)b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(3));
  });

  const GraphError error = only_error(graph);
  EXPECT_EQ(error.kind, ErrorKind::conflicting_usage);
  EXPECT_TRUE(mentions(error.message, "sampled_fragment (read, mip 0, layers 0-3)"));
  EXPECT_TRUE(mentions(error.message, "depth_attachment (write, mip 0, layer 3)"));
}

TEST_F(DeclarationErrors, DisjointLayersAndCompatibleReadsDoNotConflict) {
  graph.add_pass("blend cascades", QueueType::graphics, [&](PassBuilder& b) {
    b.read(atlas, Usage::sampled_fragment, SubresourceRange::layers(0, 4));
    b.read(atlas, Usage::depth_attachment, SubresourceRange::layer(2));  // same read-only layout
    (void)b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(4));
  });
  EXPECT_TRUE(graph.errors().empty());
}

TEST_F(DeclarationErrors, WritingAnImportWithoutAFinalState) {
  const ImageHandle history = graph.import_image("taa history", screen_color_desc, sampled_in_fragment);
  graph.add_pass("resolve", QueueType::graphics,
                 [&](PassBuilder& b) { (void)b.write(history, Usage::color_attachment); });

  const GraphError error = only_error(graph);
  EXPECT_EQ(error.kind, ErrorKind::missing_final_state);
  EXPECT_TRUE(mentions(error.message, "'resolve' writes imported 'taa history'"));
}

TEST_F(DeclarationErrors, UsagesThatDoNotExistInThatDirectionOrKind) {
  const BufferHandle lights = graph.import_buffer("lights", {4096}, {});
  graph.add_pass("nonsense", QueueType::graphics, [&](PassBuilder& b) {
    (void)b.write(atlas, Usage::sampled_fragment);
    b.read(atlas, Usage::color_attachment);
    b.read(lights, Usage::depth_attachment);
    b.read(atlas, Usage::indirect);
  });

  const CompileResult result = compile(graph);
  ASSERT_EQ(result.errors.size(), 4u);
  for (const GraphError& error : result.errors) EXPECT_EQ(error.kind, ErrorKind::invalid_usage);
  EXPECT_TRUE(mentions(result.errors[0].message, "cannot write 'shadow atlas' as sampled_fragment"));
  EXPECT_TRUE(mentions(result.errors[2].message, "cannot read 'lights' as depth_attachment"));
}

TEST_F(DeclarationErrors, RangesOutsideTheImage) {
  graph.add_pass("spot 16", QueueType::graphics, [&](PassBuilder& b) {
    (void)b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(16));
  });
  graph.add_pass("mip 1", QueueType::graphics,
                 [&](PassBuilder& b) { b.read(atlas, Usage::sampled_fragment, SubresourceRange::mip(1)); });
  graph.import_image("cubes", cube_array_desc, {{SubresourceRange::cube(4), sampled_in_fragment}});

  const CompileResult result = compile(graph);
  ASSERT_EQ(result.errors.size(), 3u);
  for (const GraphError& error : result.errors) EXPECT_EQ(error.kind, ErrorKind::invalid_range);
  EXPECT_TRUE(mentions(result.errors[0].message, "'spot 16' uses 'shadow atlas' at mips 0-last, layer 16"));
  EXPECT_TRUE(mentions(result.errors[2].message, "import of 'cubes'"));
}

TEST_F(DeclarationErrors, HandlesFromAnotherGraphOrNowhere) {
  RenderGraph other;
  const BufferHandle foreign = other.import_buffer("a", {16}, {});
  graph.add_pass("confused", QueueType::compute, [&](PassBuilder& b) {
    b.read(foreign, Usage::storage_compute);  // index 0 is an image in this graph
    b.read(ImageHandle{}, Usage::sampled_compute);
    b.read(ImageHandle{atlas.index, 5}, Usage::sampled_compute);
  });

  const CompileResult result = compile(graph);
  ASSERT_EQ(result.errors.size(), 3u);
  for (const GraphError& error : result.errors) EXPECT_EQ(error.kind, ErrorKind::invalid_handle);
}

TEST_F(DeclarationErrors, CompileReportsEveryErrorAndNoPlan) {
  graph.add_pass("a", QueueType::graphics, [&](PassBuilder& b) { b.read(atlas, Usage::color_attachment); });
  graph.add_pass("b", QueueType::graphics, [&](PassBuilder& b) {
    b.read(atlas, Usage::sampled_fragment, SubresourceRange::layer(99));
  });

  const CompileResult result = compile(graph);
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(result.plan, nullptr);
  ASSERT_EQ(result.errors.size(), 2u);
  EXPECT_EQ(result.errors[0].kind, ErrorKind::invalid_usage);
  EXPECT_EQ(result.errors[1].kind, ErrorKind::invalid_range);
}

}  // namespace
}  // namespace sg::rg
