// SPDX-License-Identifier: MIT
#pragma once
// The raster bench's cases. Each measures one limit of depth-only rasterization and reports
// one row per variant through Bench::emit, as soon as it is measured.
#include <cstdint>
#include <functional>
#include <string>

#include "bench_gpu.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/unique_handle.h"
#include "report.h"

namespace sg::raster_bench {

// The full sizes are the ones the brief for a GPU asks for; quick_sizes() shrinks every case
// so that a CPU device (lavapipe) finishes in seconds, for the smoke test.
struct BenchSizes {
  uint32_t repetitions = 7;
  // 1. Triangle throughput: grid meshes of 2 px and of 1 px cells (2 and 0.5 px per triangle),
  //    stacked back to front in one instanced draw up to about `triangles`.
  uint32_t triangle_target = 1024;
  uint32_t triangles = 4u << 20;
  // 2. Depth fill: `fill_layers` full-screen quads in one instanced draw.
  uint32_t fill_target = 2048;
  uint32_t fill_layers = 64;
  // 3. Per-pass overhead: `passes` passes of one triangle, each into its own layer (layers wrap
  //    around at `pass_layers` or the device's limit).
  uint32_t passes = 1000;
  uint32_t pass_target = 256;
  uint32_t pass_layers = 2048;
  // 4. Per-draw overhead: `draws` one-triangle draws in one pass.
  uint32_t draws = 10000;
  uint32_t draw_target = 256;
  // 5. Tile views: tiles_per_row^2 views of tile_size^2 pixels, each a grid of tile_cells^2 cells.
  uint32_t tiles_per_row = 64;
  uint32_t tile_size = 64;
  uint32_t tile_cells = 8;
};
BenchSizes quick_sizes();

// Push constants of shaders/layers.vert: instance i is drawn at depth first_depth + i * depth_step.
struct LayerDepths {
  float first_depth = 0.5f;
  float depth_step = 0.0f;
};

// The two depth-only pipelines (no fragment shader, D32_SFLOAT, LESS, depth writes, no culling).
struct BenchPipelines {
  explicit BenchPipelines(vk::VulkanContext& context);
  vk::PipelineLayout layers_layout;  // push constants: LayerDepths
  vk::UniquePipeline layers;         // shaders/layers.vert
  vk::PipelineLayout tiles_layout;   // push constants: tiles per row
  vk::UniquePipeline tiles;          // shaders/tiles.vert
};

struct Bench {
  vk::VulkanContext& context;
  BenchSizes sizes;
  const BenchPipelines& pipelines;
  std::function<void(Result)> emit;
};

// "1024x1024", for the variants' descriptions.
std::string square(uint32_t size);

// A line on stderr before a case runs, so a long run shows where it is (stdout keeps the table).
void progress(const std::string& what);

void triangle_throughput(Bench& bench);
void depth_fill(Bench& bench);
void pass_overhead(Bench& bench);
void draw_overhead(Bench& bench);
void tile_views(Bench& bench);

}  // namespace sg::raster_bench
