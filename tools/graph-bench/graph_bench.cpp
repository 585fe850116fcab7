// SPDX-License-Identifier: MIT
// Cost of building and compiling a frame graph shaped like Shadowgraph's frames: one G-buffer
// pass, many shadow passes (spot lights into layers of a 2D atlas, point lights into faces of a
// cube-map array; every tenth light renders moments into a transient and blurs them into the
// atlas), and one lighting pass reading all of it into the swapchain.
//
//   shadowgraph-graph-bench --benchmark_filter=5000
#include <benchmark/benchmark.h>

#include <string>

#include "rendergraph/core/compile.h"
#include "rendergraph/core/plan_cache.h"

namespace {

using namespace sg::rg;

constexpr ImageDesc atlas_desc{4096, 4096, Format::d32_sfloat, 64, 1, false};
constexpr ImageDesc cubes_desc{1024, 1024, Format::d16_unorm, 6 * 128, 1, true};
constexpr ResourceState sampled{PipelineStage::fragment_shader, Access::shader_sampled_read,
                                ImageLayout::read_only_optimal};

void add_gbuffer(RenderGraph& graph, ImageHandle& depth, ImageHandle& normals) {
  graph.add_pass("gbuffer", QueueType::graphics, [&](PassBuilder& b) {
    depth = b.write(b.create_image("depth", {1920, 1080, Format::d32_sfloat}), Usage::depth_attachment);
    normals =
        b.write(b.create_image("normals", {1920, 1080, Format::rgba16_sfloat}), Usage::color_attachment);
  });
}

// `passes` in all; shadow passes fill what the G-buffer and lighting passes leave.
RenderGraph build_frame(std::uint32_t passes) {
  RenderGraph graph;
  ImageHandle swapchain =
      graph.import_image("swapchain", {1920, 1080, Format::bgra8_srgb},
                         {PipelineStage::color_attachment_output, Access::none, ImageLayout::undefined},
                         ResourceState{PipelineStage::none, Access::none, ImageLayout::present_src});
  if (passes == 1) {
    graph.add_pass("clear", QueueType::graphics,
                   [&](PassBuilder& b) { swapchain = b.write(swapchain, Usage::color_attachment); });
    return graph;
  }
  ImageHandle atlas = graph.import_image("shadow atlas", atlas_desc, sampled, sampled);
  ImageHandle cubes = graph.import_image("point shadows", cubes_desc, sampled, sampled);
  ImageHandle depth{};
  ImageHandle normals{};
  add_gbuffer(graph, depth, normals);

  std::uint32_t spot = 0;
  std::uint32_t face = 0;
  for (std::uint32_t shadow = 0; shadow + 2 < passes; ++shadow) {
    const std::string light = std::to_string(shadow);
    if (shadow % 10 == 8 && shadow + 3 < passes) {
      ImageHandle moments{};
      graph.add_pass("moments " + light, QueueType::graphics, [&](PassBuilder& b) {
        moments = b.write(b.create_image("moments " + light, {1024, 1024, Format::rg16_sfloat}),
                          Usage::color_attachment);
      });
      graph.add_pass("blur " + light, QueueType::compute, [&](PassBuilder& b) {
        b.read(moments, Usage::sampled_compute);
        atlas = b.write(atlas, Usage::storage_compute, SubresourceRange::layer(spot++ % atlas_desc.layers));
      });
      ++shadow;
    } else if (shadow % 2 == 0) {
      graph.add_pass("spot " + light, QueueType::graphics, [&](PassBuilder& b) {
        atlas = b.write(atlas, Usage::depth_attachment, SubresourceRange::layer(spot++ % atlas_desc.layers));
      });
    } else {
      graph.add_pass("point face " + light, QueueType::graphics, [&](PassBuilder& b) {
        cubes = b.write(cubes, Usage::depth_attachment, SubresourceRange::layer(face++ % cubes_desc.layers));
      });
    }
  }
  graph.add_pass("lighting", QueueType::graphics, [&](PassBuilder& b) {
    b.read(depth, Usage::sampled_fragment);
    b.read(normals, Usage::sampled_fragment);
    b.read(atlas, Usage::sampled_fragment);
    b.read(cubes, Usage::sampled_fragment);
    swapchain = b.write(swapchain, Usage::color_attachment);
  });
  return graph;
}

void set_counters(benchmark::State& state, std::uint32_t passes) {
  state.counters["passes"] = passes;
  state.counters["us_per_pass"] = benchmark::Counter(
      static_cast<double>(passes) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::kIs1000);
}

void build_only(benchmark::State& state) {
  const auto passes = static_cast<std::uint32_t>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(build_frame(passes));
  set_counters(state, passes);
}

void build_and_compile(benchmark::State& state) {
  const auto passes = static_cast<std::uint32_t>(state.range(0));
  for (auto _ : state) {
    const RenderGraph graph = build_frame(passes);
    CompileResult result = compile(graph);  // not const: benchmark 1.8 deprecates DoNotOptimize(const&)
    if (!result.ok()) state.SkipWithError(result.errors.front().message.c_str());
    benchmark::DoNotOptimize(result.plan);
  }
  set_counters(state, passes);
}

// A frame whose shape matches the previous one: build, compute the shape, reuse the plan.
void build_and_reuse_cached(benchmark::State& state) {
  const auto passes = static_cast<std::uint32_t>(state.range(0));
  PlanCache cache;
  (void)cache.get_or_compile(build_frame(passes));
  for (auto _ : state) {
    const RenderGraph graph = build_frame(passes);
    benchmark::DoNotOptimize(cache.get_or_compile(graph).plan);
  }
  if (cache.misses() != 1) state.SkipWithError("the cache missed a frame of unchanged shape");
  set_counters(state, passes);
}

BENCHMARK(build_only)->Arg(1)->Arg(100)->Arg(5000)->Unit(benchmark::kMicrosecond);
BENCHMARK(build_and_compile)->Arg(1)->Arg(100)->Arg(5000)->Unit(benchmark::kMicrosecond);
BENCHMARK(build_and_reuse_cached)->Arg(1)->Arg(100)->Arg(5000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
