// SPDX-License-Identifier: MIT
// Cases 1, 2 and 5: how fast the rasterizer sets up triangles and tests depth, with the work
// in as few commands as possible so that command costs do not count.
#include <algorithm>
#include <string>
#include <vector>

#include "bench_cases.h"
#include "rendergraph/device/context.h"

namespace sg::raster_bench {
namespace {

// `layers` copies of `mesh` in one instanced draw into a cleared size x size target; the
// first copy at depth 0.75, each next one nearer (back to front) or farther (front to back).
std::vector<double> time_layers(Bench& bench, const GridMesh& mesh, uint32_t size, uint32_t layers,
                                bool back_to_front) {
  const vk::Image target = make_depth_target(bench.context, size);
  const float span = 0.5f / float(layers);
  const LayerDepths depths = back_to_front ? LayerDepths{0.75f, -span} : LayerDepths{0.25f, span};
  return time_repetitions(
      bench.context, bench.sizes.repetitions, [&](VkCommandBuffer cmd) { begin_depth_writes(cmd, target); },
      [&](VkCommandBuffer cmd) {
        begin_depth_pass(cmd, target.view(), size, VK_ATTACHMENT_LOAD_OP_CLEAR);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bench.pipelines.layers.get());
        bench.pipelines.layers_layout.push(cmd, depths);
        bind_mesh(cmd, mesh);
        vkCmdDrawIndexed(cmd, mesh.index_count, layers, 0, 0, 0);
        vkCmdEndRendering(cmd);
      });
}

}  // namespace

// Grids whose cells are 2 px and 1 px wide: triangles of 2 and 0.5 px, so the rasterizer's
// setup, not the depth test, is the limit. Shared vertices keep vertex shading to about half a
// vertex per triangle, as in an indexed caster mesh. Back to front, so every triangle is drawn.
void triangle_throughput(Bench& bench) {
  const uint32_t size = bench.sizes.triangle_target;
  for (const uint32_t cell_px : {2u, 1u}) {
    const GridMesh mesh = make_grid_mesh(bench.context, size / cell_px);
    const uint32_t layers = std::max(1u, bench.sizes.triangles / mesh.triangle_count());
    const uint64_t triangles = uint64_t{mesh.triangle_count()} * layers;
    progress("triangle throughput: " + std::to_string(triangles) + " triangles of " +
             (cell_px == 2 ? "2" : "0.5") + " px");
    bench.emit({"triangle throughput",
                std::string(cell_px == 2 ? "2 px" : "0.5 px") + " triangles, 1 draw, " + square(size),
                triangles, "triangles", Metric::giga_per_second, "Gtri/s",
                time_layers(bench, mesh, size, layers, true)});
  }
}

// Full-screen quads stacked in one draw. Back to front, every pixel of every layer passes the
// test and writes: the fill rate. Front to back, every layer after the first fails the test:
// the rate at which hidden pixels are rejected. The pass's clear is in the time (one layer's
// worth of pixels among `fill_layers`). Flat screen-sized planes are the best case for depth
// compression and hierarchical depth (and CPU drivers may skip covered work), so this is an
// upper bound: casters' small triangles fill slower.
void depth_fill(Bench& bench) {
  const uint32_t size = bench.sizes.fill_target;
  const uint32_t layers = bench.sizes.fill_layers;
  const GridMesh quad = make_grid_mesh(bench.context, 1);
  const uint64_t pixels = uint64_t{size} * size * layers;
  for (const bool back_to_front : {true, false}) {
    const char* order = back_to_front ? "back to front" : "front to back";
    progress(std::string("depth fill: ") + std::to_string(layers) + " full-screen layers " + order);
    bench.emit({"depth fill", std::to_string(layers) + " quads " + order + ", " + square(size), pixels,
                "pixels", Metric::giga_per_second, "Gpx/s",
                time_layers(bench, quad, size, layers, back_to_front)});
  }
}

// Shadow-atlas-like tiles: many small views in one big target, in one pass, (a) as one
// multi-draw indirect call whose vertex shader moves each draw into its tile, (b) as a viewport
// and scissor per view and one vkCmdDrawIndexed each (what a renderer without indirect draws
// does). The figure is the time per view.
void tile_views(Bench& bench) {
  const uint32_t per_row = bench.sizes.tiles_per_row;
  const uint32_t tile = bench.sizes.tile_size;
  const uint32_t size = per_row * tile;
  const uint32_t views = per_row * per_row;
  const GridMesh mesh = make_grid_mesh(bench.context, bench.sizes.tile_cells);
  std::vector<VkDrawIndexedIndirectCommand> commands;
  for (uint32_t view = 0; view < views; ++view) commands.push_back({mesh.index_count, 1, 0, 0, view});
  const vk::Buffer draws = make_indirect_buffer(bench.context, commands);
  const vk::Image target = make_depth_target(bench.context, size);
  const auto setup = [&](VkCommandBuffer cmd) { begin_depth_writes(cmd, target); };
  const std::string variant =
      std::to_string(mesh.triangle_count()) + " triangles per " + square(tile) + " view, " + square(size);
  progress("tile views: " + std::to_string(views) + " views of " + square(tile));

  bench.emit({"tile views", "1 multi-draw indirect, " + variant, views, "views", Metric::nanoseconds_each,
              "ns/view",
              time_repetitions(bench.context, bench.sizes.repetitions, setup, [&](VkCommandBuffer cmd) {
                begin_depth_pass(cmd, target.view(), size, VK_ATTACHMENT_LOAD_OP_CLEAR);
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bench.pipelines.tiles.get());
                bench.pipelines.tiles_layout.push(cmd, per_row);
                bind_mesh(cmd, mesh);
                draw_indexed_indirect(cmd, bench.context, draws, views);
                vkCmdEndRendering(cmd);
              })});

  bench.emit({"tile views", "viewport + draw per view, " + variant, views, "views", Metric::nanoseconds_each,
              "ns/view",
              time_repetitions(bench.context, bench.sizes.repetitions, setup, [&](VkCommandBuffer cmd) {
                begin_depth_pass(cmd, target.view(), size, VK_ATTACHMENT_LOAD_OP_CLEAR);
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bench.pipelines.layers.get());
                bench.pipelines.layers_layout.push(cmd, LayerDepths{});
                bind_mesh(cmd, mesh);
                for (uint32_t view = 0; view < views; ++view) {
                  const VkRect2D rect{{int32_t(view % per_row * tile), int32_t(view / per_row * tile)},
                                      {tile, tile}};
                  const VkViewport viewport{
                      float(rect.offset.x), float(rect.offset.y), float(tile), float(tile), 0.0f, 1.0f};
                  vkCmdSetViewport(cmd, 0, 1, &viewport);
                  vkCmdSetScissor(cmd, 0, 1, &rect);
                  vkCmdDrawIndexed(cmd, mesh.index_count, 1, 0, 0, 0);
                }
                vkCmdEndRendering(cmd);
              })});
}

}  // namespace sg::raster_bench
