// SPDX-License-Identifier: MIT
#pragma once
// Median, min and max of per-frame samples: how runs and tools report times and counts.
#include <optional>
#include <span>
#include <string>

namespace sg {

struct TimeSummary {
  double median = 0.0;  // the mean of the two middle samples when their count is even
  double min = 0.0;
  double max = 0.0;
};

// std::nullopt for no samples: there is nothing to summarize, and zeros would read as a
// measurement.
std::optional<TimeSummary> summarize(std::span<const double> samples);

struct PassTime {
  std::string name;
  TimeSummary gpu_ms;
};

}  // namespace sg
