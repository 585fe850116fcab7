// SPDX-License-Identifier: MIT
// Cases 3 and 4: what a render pass and a draw cost in themselves, with as little raster work
// as possible in them (one triangle of a few pixels each), so the command's own cost shows.
#include <algorithm>
#include <string>
#include <vector>

#include "bench_cases.h"
#include "rendergraph/device/context.h"

namespace sg::raster_bench {
namespace {

// Triangles of 2 px (cells of 2 px), or smaller when the draws need more of them than that.
GridMesh tiny_triangles(Bench& bench, uint32_t target, uint32_t at_least) {
  uint32_t cells = target / 2;
  while (2 * cells * cells < at_least) cells *= 2;
  return make_grid_mesh(bench.context, cells);
}

}  // namespace

// `passes` passes one after the other, each with one triangle, each into the next layer of a
// 2D-array target, as shadow passes render into the layers of a shadow-map array. The pipeline
// and buffers are bound once, so the figure is a pass's own cost plus one small draw. Loading
// keeps the previous contents (the layers are cleared once, untimed); clearing is what a shadow
// pass does each frame.
void pass_overhead(Bench& bench) {
  const uint32_t size = bench.sizes.pass_target;
  const uint32_t passes = bench.sizes.passes;
  const VkPhysicalDeviceLimits& limits = bench.context.properties().limits;
  const uint32_t layers =
      std::min({bench.sizes.pass_layers, passes, limits.maxImageArrayLayers, limits.maxFramebufferLayers});
  const vk::Image target = make_depth_target(bench.context, size, layers);
  std::vector<VkImageView> views;
  for (uint32_t layer = 0; layer < layers; ++layer) views.push_back(target.views().get({0, 1, layer, 1}));
  const GridMesh mesh = tiny_triangles(bench, size, 1);
  const auto setup = [&](VkCommandBuffer cmd) {
    begin_depth_writes(cmd, target);
    begin_depth_pass(cmd, target.view(), size, VK_ATTACHMENT_LOAD_OP_CLEAR, layers);
    vkCmdEndRendering(cmd);
  };
  for (const VkAttachmentLoadOp load : {VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_LOAD_OP_CLEAR}) {
    const char* op = load == VK_ATTACHMENT_LOAD_OP_LOAD ? "load" : "clear";
    progress("pass overhead: " + std::to_string(passes) + " passes, " + op);
    bench.emit(
        {"pass overhead",
         std::string(op) + ", 1 triangle, " + square(size) + " x " + std::to_string(layers) + " layers",
         passes, "passes", Metric::microseconds_each, "us/pass",
         time_repetitions(bench.context, bench.sizes.repetitions, setup, [&](VkCommandBuffer cmd) {
           vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bench.pipelines.layers.get());
           bench.pipelines.layers_layout.push(cmd, LayerDepths{});
           bind_mesh(cmd, mesh);
           for (uint32_t pass = 0; pass < passes; ++pass) {
             begin_depth_pass(cmd, views[pass % layers], size, load);
             vkCmdDrawIndexed(cmd, 3, 1, 0, 0, 0);
             vkCmdEndRendering(cmd);
           }
         })});
  }
}

// `draws` draws of one triangle each (a different one each time) in one pass: (a) as separate
// vkCmdDrawIndexed calls, (b) as one vkCmdDrawIndexedIndirect call with a command per draw.
void draw_overhead(Bench& bench) {
  const uint32_t size = bench.sizes.draw_target;
  const uint32_t count = bench.sizes.draws;
  const GridMesh mesh = tiny_triangles(bench, size, count);
  std::vector<VkDrawIndexedIndirectCommand> commands;
  for (uint32_t draw = 0; draw < count; ++draw) commands.push_back({3, 1, 3 * draw, 0, 0});
  const vk::Buffer indirect = make_indirect_buffer(bench.context, commands);
  const vk::Image target = make_depth_target(bench.context, size);
  const auto setup = [&](VkCommandBuffer cmd) { begin_depth_writes(cmd, target); };
  const auto in_pass = [&](auto draw_all) {
    return [&, draw_all](VkCommandBuffer cmd) {
      begin_depth_pass(cmd, target.view(), size, VK_ATTACHMENT_LOAD_OP_CLEAR);
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bench.pipelines.layers.get());
      bench.pipelines.layers_layout.push(cmd, LayerDepths{});
      bind_mesh(cmd, mesh);
      draw_all(cmd);
      vkCmdEndRendering(cmd);
    };
  };
  const std::string variant = ", 1 triangle each, " + square(size);
  progress("draw overhead: " + std::to_string(count) + " draws");

  bench.emit(
      {"draw overhead", "vkCmdDrawIndexed per draw" + variant, count, "draws", Metric::nanoseconds_each,
       "ns/draw",
       time_repetitions(bench.context, bench.sizes.repetitions, setup, in_pass([&](VkCommandBuffer cmd) {
                          for (uint32_t draw = 0; draw < count; ++draw)
                            vkCmdDrawIndexed(cmd, 3, 1, 3 * draw, 0, 0);
                        }))});
  bench.emit(
      {"draw overhead", "1 multi-draw indirect" + variant, count, "draws", Metric::nanoseconds_each,
       "ns/draw",
       time_repetitions(bench.context, bench.sizes.repetitions, setup, in_pass([&](VkCommandBuffer cmd) {
                          draw_indexed_indirect(cmd, bench.context, indirect, count);
                        }))});
}

}  // namespace sg::raster_bench
