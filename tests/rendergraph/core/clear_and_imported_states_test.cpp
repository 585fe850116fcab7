// SPDX-License-Identifier: MIT
// Attachment clears as declarations, and carrying imported states from frame to frame.
#include <gtest/gtest.h>

#include "rendergraph/core/graph_shape.h"
#include "rendergraph/core/imported_states.h"
#include "test_graphs.h"

namespace sg::rg {
namespace {

using namespace sg::rg::testing;

TEST(AttachmentClear, IsRecordedOnTheWriteAccess) {
  RenderGraph graph;
  graph.add_pass("shadow", QueueType::graphics, [&](PassBuilder& b) {
    ImageHandle depth = b.create_image("depth", shadow_atlas_desc);
    (void)b.write(depth, Usage::depth_attachment, ClearValue::depth_of(0.25f), SubresourceRange::layer(3));
  });
  const ResourceAccess& access = graph.passes()[0].accesses[0];
  ASSERT_TRUE(access.clear.has_value());
  EXPECT_EQ(access.clear->depth, 0.25f);
  EXPECT_EQ(access.range, (SubresourceRange{0, 1, 3, 1}));
}

// A write without a clear keeps what the resource held before: an earlier pass's version or an
// imported resource's contents. A transient's first write holds nothing to keep (the executor
// loads nothing there).
TEST(AttachmentClear, OnlyATransientsFirstWriteHasNoEarlierContents) {
  RenderGraph graph;
  ImageHandle atlas =
      graph.import_image("atlas", shadow_atlas_desc, sampled_in_fragment, sampled_in_fragment);
  ImageHandle color;
  graph.add_pass("first", QueueType::graphics, [&](PassBuilder& b) {
    color = b.write(b.create_image("color", screen_color_desc), Usage::color_attachment);
    atlas = b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(0));
  });
  graph.add_pass("second", QueueType::graphics,
                 [&](PassBuilder& b) { color = b.write(color, Usage::color_attachment); });
  ASSERT_TRUE(graph.errors().empty());
  const std::vector<ResourceAccess>& first = graph.passes()[0].accesses;
  ASSERT_EQ(first.size(), 2u);
  EXPECT_FALSE(has_earlier_contents(first[0], false)) << "the transient's first write";
  EXPECT_TRUE(has_earlier_contents(first[1], true)) << "the imported atlas";
  EXPECT_TRUE(has_earlier_contents(graph.passes()[1].accesses[0], false)) << "the transient's second write";
}

// A pass that tests against a depth buffer without writing it reads the first pass's version:
// it must load it (VK_ATTACHMENT_LOAD_OP_LOAD), not take it as undefined.
TEST(AttachmentClear, AReadOnlyAttachmentOfAFirstWriteHasEarlierContents) {
  RenderGraph graph;
  ImageHandle depth;
  graph.add_pass("opaque", QueueType::graphics, [&](PassBuilder& b) {
    depth = b.write(b.create_image("depth", ImageDesc{1280, 720, Format::d32_sfloat, 1, 1, false}),
                    Usage::depth_attachment, ClearValue::depth_of(1.0f));
  });
  graph.add_pass("transparent", QueueType::graphics,
                 [&](PassBuilder& b) { b.read(depth, Usage::depth_attachment); });
  ASSERT_TRUE(graph.errors().empty());
  const ResourceAccess& test = graph.passes()[1].accesses[0];
  ASSERT_EQ(test.direction, Direction::read);
  EXPECT_TRUE(has_earlier_contents(test, false));
}

TEST(AttachmentClear, IsRefusedForUsagesThatAreNotAttachments) {
  RenderGraph graph;
  graph.add_pass("copy", QueueType::transfer, [&](PassBuilder& b) {
    ImageHandle image = b.create_image("image", screen_color_desc);
    (void)b.write(image, Usage::transfer, ClearValue::color_of(1, 0, 0));
  });
  ASSERT_EQ(graph.errors().size(), 1u);
  EXPECT_EQ(graph.errors()[0].kind, ErrorKind::invalid_usage);
  EXPECT_TRUE(mentions(graph.errors()[0].message, "only attachment writes can clear"));
}

TEST(AttachmentClear, ChangesTheShapeButItsValueDoesNot) {
  const auto shape_with = [](std::optional<ClearValue> clear) {
    RenderGraph graph;
    graph.add_pass("color", QueueType::graphics, [&](PassBuilder& b) {
      ImageHandle image = b.create_image("image", screen_color_desc);
      image =
          clear ? b.write(image, Usage::color_attachment, *clear) : b.write(image, Usage::color_attachment);
      b.mark_side_effects();
    });
    return graph_shape(graph);
  };
  EXPECT_NE(shape_with(std::nullopt), shape_with(ClearValue::color_of(0, 0, 0)));
  EXPECT_EQ(shape_with(ClearValue::color_of(0, 0, 0)), shape_with(ClearValue::color_of(1, 1, 1)));
}

// The atlas is written layer by layer and sampled; the next frame's import must start from the
// sampled state the plan left it in.
CompileResult atlas_frame(ImportedStates& states) {
  RenderGraph graph;
  ImageHandle atlas =
      graph.import_image("atlas", shadow_atlas_desc, states.initial_states("atlas"), sampled_in_fragment);
  graph.add_pass("spot", QueueType::graphics, [&](PassBuilder& b) {
    atlas = b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(0));
  });
  return compile(graph);
}

TEST(ImportedStates, UnknownNamesStartUndefined) {
  const ImportedStates states;
  EXPECT_TRUE(states.initial_states("atlas").empty());
}

TEST(ImportedStates, TheNextFrameStartsWhereThePlanLeftTheResource) {
  ImportedStates states;
  const CompileResult first = atlas_frame(states);
  ASSERT_TRUE(first.ok());
  states.remember(*first.plan);
  const std::vector<RangeState> initial = states.initial_states("atlas");
  ASSERT_EQ(initial.size(), 1u);
  EXPECT_EQ(initial[0].state, sampled_in_fragment);
  EXPECT_EQ(initial[0].range, (SubresourceRange{0, 1, 0, shadow_atlas_desc.layers}));

  // Frame 2's barrier for layer 0 transitions from the sampled layout, not from undefined.
  const CompileResult second = atlas_frame(states);
  ASSERT_TRUE(second.ok());
  const ImageBarrier& barrier = second.plan->passes[0].barriers.images.at(0);
  EXPECT_EQ(barrier.dependency.old_layout, sampled_in_fragment.layout);
  EXPECT_NE(barrier.dependency.old_layout, ImageLayout::undefined);

  states.forget("atlas");
  EXPECT_TRUE(states.initial_states("atlas").empty());
}

}  // namespace
}  // namespace sg::rg
