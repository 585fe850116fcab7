// SPDX-License-Identifier: MIT
#pragma once
// The raster bench's results: one row per case variant, printed as a Markdown table as they
// come and written as CSV at the end.
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace sg::raster_bench {

// How a row's figure is derived from its median time and its item count.
enum class Metric {
  giga_per_second,    // items / median, in billions per second (triangles, pixels)
  microseconds_each,  // median / items (passes, views)
  nanoseconds_each,   // median / items (draws)
};

struct Result {
  std::string name;     // the case, e.g. "triangle throughput"
  std::string variant;  // what distinguishes rows of one case, with the target's size
  uint64_t items = 0;   // what the figure counts
  std::string item;     // its name, plural: "triangles"
  Metric metric = Metric::giga_per_second;
  std::string unit;        // the figure's unit, e.g. "Gtri/s"
  std::vector<double> ms;  // GPU milliseconds of each timed repetition
};

double median(std::vector<double> values);
double figure(const Result& result);

void print_table_header(std::FILE* out);
void print_table_row(std::FILE* out, const Result& result);
// A header line and one line per result; the caller checks the stream.
void write_csv(std::ostream& out, const std::vector<Result>& results);

}  // namespace sg::raster_bench
