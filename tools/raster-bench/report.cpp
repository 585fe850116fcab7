// SPDX-License-Identifier: MIT
#include "report.h"

#include <algorithm>

namespace sg::raster_bench {
namespace {

// 4194304 -> "4,194,304": counts of millions are read at a glance.
std::string with_commas(uint64_t value) {
  const std::string digits = std::to_string(value);
  std::string text;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
    text += digits[i];
  }
  return text;
}

}  // namespace

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

double figure(const Result& result) {
  const double seconds = median(result.ms) * 1e-3;
  const double items = double(result.items);
  switch (result.metric) {
    case Metric::giga_per_second: return seconds > 0.0 ? items / seconds * 1e-9 : 0.0;
    case Metric::microseconds_each: return seconds / items * 1e6;
    case Metric::nanoseconds_each: return seconds / items * 1e9;
  }
  return 0.0;
}

void print_table_header(std::FILE* out) {
  std::fprintf(out, "| case | variant | work | median (ms) | min (ms) | max (ms) | result |\n");
  std::fprintf(out, "|---|---|---:|---:|---:|---:|---:|\n");
}

void print_table_row(std::FILE* out, const Result& r) {
  const auto [min, max] = std::minmax_element(r.ms.begin(), r.ms.end());
  std::fprintf(out, "| %s | %s | %s %s | %.4f | %.4f | %.4f | %.3f %s |\n", r.name.c_str(), r.variant.c_str(),
               with_commas(r.items).c_str(), r.item.c_str(), median(r.ms), *min, *max, figure(r),
               r.unit.c_str());
  std::fflush(out);
}

void write_csv(std::ostream& csv, const std::vector<Result>& results) {
  csv << "case,variant,items,item,repetitions,median_ms,min_ms,max_ms,result,unit\n";
  for (const Result& r : results) {
    const auto [min, max] = std::minmax_element(r.ms.begin(), r.ms.end());
    csv << '"' << r.name << "\",\"" << r.variant << "\"," << r.items << ',' << r.item << ',' << r.ms.size()
        << ',' << median(r.ms) << ',' << *min << ',' << *max << ',' << figure(r) << ',' << r.unit << '\n';
  }
}

}  // namespace sg::raster_bench
