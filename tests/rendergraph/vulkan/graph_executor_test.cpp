// SPDX-License-Identifier: MIT
// The Vulkan executor on lavapipe with validation and synchronization validation on: what the
// compiled plan says is what the GPU does, and the barriers it records satisfy the layer.
#include <cmath>
#include <memory>
#include <stdexcept>

#include <gtest/gtest.h>

#include "rendergraph/core/compile.h"
#include "rendergraph/device/barriers.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/graph_executor.h"
#include "rendergraph/vulkan/graph_imports.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

using namespace sg::rg;

constexpr uint32_t size = 16;
constexpr ImageDesc color_desc{size, size, Format::rgba8_unorm};
constexpr ResourceState transfer_source{PipelineStage::all_transfer, Access::transfer_read,
                                        ImageLayout::transfer_src_optimal};

class GraphExecutorTest : public GpuTest {
 protected:
  vk::Image output = vk::Image(context, {{size, size},
                                         VK_FORMAT_R8G8B8A8_UNORM,
                                         VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                         1,
                                         1,
                                         VK_IMAGE_VIEW_TYPE_2D,
                                         "test output"});
  vk::FrameRing frames{context};
  vk::GraphExecutor executor{context, frames.frames_in_flight()};
  vk::GraphImports imports;

  ImageHandle import_output(RenderGraph& graph) {
    return imports.import_image(graph, "output", output, transfer_source);
  }

  // Compiles and runs one frame, then remembers the imported states for the next.
  void run(RenderGraph& graph) {
    CompileResult compiled = compile(graph);
    ASSERT_TRUE(compiled.errors.empty()) << compiled.errors.front().message;
    vk::FrameSlot& frame = frames.begin_frame();
    executor.execute(frame.cmd, frame.slot, frame.frame_number, graph, compiled.plan, imports.resources());
    frames.submit();
    imports.remember(*compiled.plan);
    last_plan = compiled.plan;
  }

  std::shared_ptr<const CompiledPlan> last_plan;
};

// A pass that copies `source` (the whole image) into `destination`.
void add_copy(RenderGraph& graph, const char* name, ImageHandle source, ImageHandle& destination) {
  graph.add_pass(
      name, QueueType::transfer,
      [&](PassBuilder& b) {
        b.read(source, Usage::transfer);
        destination = b.write(destination, Usage::transfer);
      },
      [source, destination](PassContext& ctx) {
        const auto& rec = ctx.get<vk::PassRecorder>();
        VkImageCopy region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.extent = {size, size, 1};
        vkCmdCopyImage(rec.cmd(), rec.image(source), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       rec.image(destination), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      });
}

// A raster pass with no draws: the attachment's clear is its whole output.
ImageHandle add_clear(RenderGraph& graph, const char* name, ClearValue clear) {
  ImageHandle image;
  graph.add_pass(name, QueueType::graphics, [&](PassBuilder& b) {
    image = b.create_image(name, color_desc);
    image = b.write(image, Usage::color_attachment, clear);
  });
  return image;
}

void expect_every_pixel(const vk::Rgba8Image& image, uint8_t r, uint8_t g, uint8_t b) {
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      ASSERT_EQ(p[0], r) << x << "," << y;
      ASSERT_EQ(p[1], g) << x << "," << y;
      ASSERT_EQ(p[2], b) << x << "," << y;
    }
  }
}

TEST_F(GraphExecutorTest, ClearsAndCopiesThroughTransientsIntoTheImportedImage) {
  RenderGraph graph;
  ImageHandle out = import_output(graph);
  const ImageHandle red = add_clear(graph, "red", ClearValue::color_of(1, 0, 0));
  add_copy(graph, "copy", red, out);
  run(graph);
  frames.wait_idle();
  expect_every_pixel(vk::read_rgba8(context, output), 255, 0, 0);
}

TEST_F(GraphExecutorTest, AliasedTransientsKeepTheirOwnContents) {
  // Two transients whose lifetimes do not overlap share memory. The later copy must see blue,
  // and synchronization validation must find the reuse of the memory properly ordered.
  RenderGraph graph;
  ImageHandle out = import_output(graph);
  const ImageHandle red = add_clear(graph, "red", ClearValue::color_of(1, 0, 0));
  add_copy(graph, "copy red", red, out);
  const ImageHandle blue = add_clear(graph, "blue", ClearValue::color_of(0, 0, 1));
  add_copy(graph, "copy blue", blue, out);
  run(graph);
  frames.wait_idle();
  EXPECT_LT(executor.transient_heap_bytes(0), executor.transient_unaliased_bytes(0))
      << "red and blue live in disjoint pass ranges and should share one allocation";
  expect_every_pixel(vk::read_rgba8(context, output), 0, 0, 255);
}

TEST_F(GraphExecutorTest, ImportedStatesCarryAcrossFramesAndLoadKeepsContents) {
  // Frame 1 fills the output green. Frame 2 renders into it with LOAD (no clear) and draws
  // nothing: the output must still be green, which needs frame 2's barrier to start from the
  // layout frame 1 left (an UNDEFINED start would discard the contents).
  {
    RenderGraph graph;
    ImageHandle out = import_output(graph);
    add_copy(graph, "copy green", add_clear(graph, "green", ClearValue::color_of(0, 1, 0)), out);
    run(graph);
  }
  {
    RenderGraph graph;
    ImageHandle out = import_output(graph);
    const std::vector<RangeState>& initial = graph.resources()[out.index].initial_states;
    ASSERT_EQ(initial.size(), 1u);
    EXPECT_EQ(initial[0].state, transfer_source);
    graph.add_pass("load only", QueueType::graphics,
                   [&](PassBuilder& b) { out = b.write(out, Usage::color_attachment); });
    run(graph);
  }
  frames.wait_idle();
  expect_every_pixel(vk::read_rgba8(context, output), 0, 255, 0);
}

TEST_F(GraphExecutorTest, ARecreatedImportStartsUndefined) {
  {
    RenderGraph graph;
    ImageHandle out = import_output(graph);
    add_copy(graph, "copy green", add_clear(graph, "green", ClearValue::color_of(0, 1, 0)), out);
    run(graph);
  }
  frames.wait_idle();
  output = vk::Image(context, {{size, size},
                               VK_FORMAT_R8G8B8A8_UNORM,
                               VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                               1,
                               1,
                               VK_IMAGE_VIEW_TYPE_2D,
                               "test output, recreated"});
  RenderGraph graph;
  ImageHandle out = import_output(graph);
  // The old image's states would make the first barrier claim a layout the new one never had.
  EXPECT_TRUE(graph.resources()[out.index].initial_states.empty());
  add_copy(graph, "copy red", add_clear(graph, "red", ClearValue::color_of(1, 0, 0)), out);
  run(graph);
  frames.wait_idle();
  expect_every_pixel(vk::read_rgba8(context, output), 255, 0, 0);
}

TEST_F(GraphExecutorTest, ReportsPerPassGpuMillisecondsAfterTheSlotComesAround) {
  ASSERT_TRUE(executor.timestamps_supported()) << "lavapipe reports timestamps";
  for (uint32_t frame = 0; frame <= frames.frames_in_flight(); ++frame) {
    RenderGraph graph;
    ImageHandle out = import_output(graph);
    add_copy(graph, "copy", add_clear(graph, "red", ClearValue::color_of(1, 0, 0)), out);
    run(graph);
  }
  frames.wait_idle();
  const auto& timings = executor.latest_timings();
  ASSERT_TRUE(timings.has_value());
  EXPECT_EQ(timings->frame_number, 0u);
  ASSERT_EQ(timings->pass_ms.size(), timings->plan->passes.size());
  ASSERT_EQ(timings->pass_ms.size(), 2u);
  for (double ms : timings->pass_ms) {
    EXPECT_TRUE(std::isfinite(ms));
    EXPECT_GE(ms, 0.0);
  }
}

TEST_F(GraphExecutorTest, AnUnboundImportIsAClearError) {
  RenderGraph graph;
  ImageHandle out = import_output(graph);
  add_copy(graph, "copy", add_clear(graph, "red", ClearValue::color_of(1, 0, 0)), out);
  const CompileResult compiled = compile(graph);
  vk::FrameSlot& frame = frames.begin_frame();
  try {
    executor.execute(frame.cmd, frame.slot, frame.frame_number, graph, compiled.plan, {});
    FAIL() << "expected an error";
  } catch (const std::logic_error& error) {
    EXPECT_NE(std::string(error.what()).find("'output'"), std::string::npos) << error.what();
  }
}

TEST_F(GraphExecutorTest, RendersIntoOneLayerOfAnImportedArrayAndLeavesTheOthers) {
  // Layer 1 of a three-layer image is cleared through a one-layer attachment view; layer 0 and
  // layer 2 keep the values an earlier pass gave them.
  vk::Image layers(context, {{size, size},
                             VK_FORMAT_R8G8B8A8_UNORM,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                             1,
                             3,
                             VK_IMAGE_VIEW_TYPE_2D_ARRAY,
                             "layers"});
  RenderGraph graph;
  const ImageDesc desc{size, size, Format::rgba8_unorm, 3};
  ImageHandle array = graph.import_image("layers", desc, ResourceState{}, transfer_source);
  graph.add_pass("all grey", QueueType::graphics, [&](PassBuilder& b) {
    array = b.write(array, Usage::color_attachment, ClearValue::color_of(0.5f, 0.5f, 0.5f));
  });
  graph.add_pass("layer 1 white", QueueType::graphics, [&](PassBuilder& b) {
    array =
        b.write(array, Usage::color_attachment, ClearValue::color_of(1, 1, 1), SubresourceRange::layer(1));
  });
  const CompileResult compiled = compile(graph);
  ASSERT_TRUE(compiled.errors.empty());
  vk::ImportedResources imports;
  imports.bind(array, layers);
  vk::FrameSlot& frame = frames.begin_frame();
  executor.execute(frame.cmd, frame.slot, frame.frame_number, graph, compiled.plan, imports);
  frames.submit();
  frames.wait_idle();

  for (uint32_t layer = 0; layer < 3; ++layer) {
    // Copy each layer into `output` to read it back.
    context.submit_and_wait([&](VkCommandBuffer cmd) {
      vk::transition(cmd, {output.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                           VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                           VK_ACCESS_2_TRANSFER_WRITE_BIT});
      VkImageCopy region{};
      region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, layer, 1};
      region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.extent = {size, size, 1};
      vkCmdCopyImage(cmd, layers.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, output.handle(),
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      vk::transition(cmd, {output.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                           VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                           VK_ACCESS_2_TRANSFER_READ_BIT});
    });
    const uint8_t expected = layer == 1 ? 255 : 128;
    SCOPED_TRACE(layer);
    expect_every_pixel(vk::read_rgba8(context, output), expected, expected, expected);
  }
}

}  // namespace
}  // namespace sg::test
