// SPDX-License-Identifier: MIT
#include "bench_cases.h"

#include <cstdio>

#include "raster_bench_shaders/layers.vert.spv.h"
#include "raster_bench_shaders/tiles.vert.spv.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"

namespace sg::raster_bench {
namespace {

vk::UniquePipeline depth_only_pipeline(vk::VulkanContext& context, std::span<const uint32_t> vertex_spirv,
                                       VkPipelineLayout layout, const char* name) {
  vk::GraphicsPipelineDesc desc;
  desc.vertex_spirv = vertex_spirv;
  desc.vertex_bindings = {{0, 2 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, 0}};
  desc.depth_format = VK_FORMAT_D32_SFLOAT;
  // Grids are drawn as they are, whatever their winding: no triangle may be culled.
  desc.cull_mode = VK_CULL_MODE_NONE;
  desc.layout = layout;
  desc.name = name;
  return vk::create_graphics_pipeline(context, desc);
}

}  // namespace

BenchSizes quick_sizes() {
  BenchSizes s;
  s.repetitions = 3;
  s.triangle_target = 128;
  s.triangles = 1u << 16;
  s.fill_target = 256;
  s.fill_layers = 4;
  s.passes = 50;
  s.pass_target = 64;
  s.pass_layers = 16;
  s.draws = 200;
  s.draw_target = 64;
  s.tiles_per_row = 16;
  s.tile_size = 16;
  s.tile_cells = 4;
  return s;
}

BenchPipelines::BenchPipelines(vk::VulkanContext& context)
    : layers_layout(context.device(), {}, vk::push_constants<LayerDepths>(VK_SHADER_STAGE_VERTEX_BIT)),
      layers(depth_only_pipeline(context, layers_vert, layers_layout.get(), "raster-bench layers")),
      tiles_layout(context.device(), {}, vk::push_constants<uint32_t>(VK_SHADER_STAGE_VERTEX_BIT)),
      tiles(depth_only_pipeline(context, tiles_vert, tiles_layout.get(), "raster-bench tiles")) {}

std::string square(uint32_t size) { return std::to_string(size) + "x" + std::to_string(size); }

void progress(const std::string& what) {
  std::fprintf(stderr, "raster-bench: %s\n", what.c_str());
  std::fflush(stderr);
}

}  // namespace sg::raster_bench
