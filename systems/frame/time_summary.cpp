// SPDX-License-Identifier: MIT
#include "systems/frame/time_summary.h"

#include <algorithm>
#include <vector>

namespace sg {

std::optional<TimeSummary> summarize(std::span<const double> samples) {
  if (samples.empty()) return std::nullopt;
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t middle = sorted.size() / 2;
  const double median = sorted.size() % 2 == 1 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2.0;
  return TimeSummary{median, sorted.front(), sorted.back()};
}

}  // namespace sg
