// SPDX-License-Identifier: MIT
// shadowgraph-raster-bench: the device's depth-only raster limits, so that shadow passes' GPU
// times can be stated as a fraction of what the hardware allows. Every case draws with a
// depth-only pipeline (D32_SFLOAT, no fragment shader) and dynamic rendering, times several
// repetitions with GPU timestamps and reports the median:
//   1. triangle throughput (Gtri/s): millions of 0.5-2 px triangles in one draw;
//   2. depth fill (Gpx/s): stacked full-screen quads, back to front and front to back;
//   3. pass overhead (us/pass): many passes of one triangle into the layers of an array;
//   4. draw overhead (ns/draw): many one-triangle draws, direct and multi-draw indirect;
//   5. tile views (ns/view): thousands of small views in one target, as a shadow atlas.
//
//   shadowgraph-raster-bench [--device NAME] [--quick] [--csv results.csv] [--validation]
#include <cstdio>
#include <exception>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_cases.h"
#include "rendergraph/device/context.h"

int main(int argc, char** argv) {
  using namespace sg::raster_bench;
  sg::vk::ContextOptions context_options;
  bool quick = false;
  std::optional<uint32_t> repetitions;
  std::string csv_path;
  CLI::App app{
      "Measures the device's depth-only raster limits: triangle rate, depth fill rate, and "
      "the cost of a pass, a draw and a small view."};
  app.add_option("--device", context_options.device_name,
                 "Use the Vulkan device whose name contains NAME (case-insensitive)")
      ->option_text("NAME");
  app.add_flag("--validation", context_options.validation,
               "Khronos validation layer on (also SHADOWGRAPH_VALIDATION=1); slows every case");
  app.add_flag("--quick", quick, "Small sizes, a few seconds on lavapipe (the smoke test)");
  app.add_option("--repetitions", repetitions,
                 "Timed repetitions per row, after one warm-up (default 7; 3 with --quick)")
      ->check(CLI::Range(1u, 1000u));
  app.add_option("--csv", csv_path, "Also write the results to this CSV file")->option_text("FILE");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) != static_cast<int>(CLI::ExitCodes::Success) ? 2 : 0;
  }
  context_options.validation = context_options.validation || sg::vk::validation_requested_by_environment();

  try {
    // Opened first, so that an unwritable path fails before minutes of measurements, not after.
    std::ofstream csv;
    if (!csv_path.empty()) csv.open(csv_path);
    if (!csv_path.empty() && !csv) throw std::runtime_error("cannot write the CSV file " + csv_path);
    sg::vk::VulkanContext context(context_options);
    BenchSizes sizes = quick ? quick_sizes() : BenchSizes{};
    if (repetitions) sizes.repetitions = *repetitions;
    const uint32_t api = context.properties().apiVersion;
    std::printf("device: %s (Vulkan %u.%u.%u)%s, median of %u repetitions per row\n\n",
                context.device_name().c_str(), VK_API_VERSION_MAJOR(api), VK_API_VERSION_MINOR(api),
                VK_API_VERSION_PATCH(api), quick ? ", quick sizes" : "", sizes.repetitions);
    print_table_header(stdout);
    const BenchPipelines pipelines(context);
    std::vector<Result> results;
    Bench bench{context, sizes, pipelines, [&](Result result) {
                  print_table_row(stdout, result);
                  results.push_back(std::move(result));
                }};
    for (void (*run_case)(Bench&) :
         {triangle_throughput, depth_fill, pass_overhead, draw_overhead, tile_views}) {
      run_case(bench);
    }
    if (csv.is_open()) {
      write_csv(csv, results);
      if (!csv.flush()) throw std::runtime_error("cannot write the CSV file " + csv_path);
    }
    if (context.validation_enabled() && context.validation_errors() > 0) {
      std::fprintf(stderr, "shadowgraph-raster-bench: the validation layer reported %u errors\n",
                   context.validation_errors());
      return 3;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowgraph-raster-bench: error: %s\n", e.what());
    return 1;
  }
}
