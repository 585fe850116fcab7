// SPDX-License-Identifier: MIT
#include "systems/frame/gpu_time_log.h"

#include <algorithm>
#include <numeric>

namespace sg {

bool GpuTimeLog::add(const std::optional<vk::FrameTimings>& timings) {
  if (!timings || (last_frame_ && *last_frame_ == timings->frame_number)) return false;
  last_frame_ = timings->frame_number;
  frame_ms_.push_back(std::accumulate(timings->pass_ms.begin(), timings->pass_ms.end(), 0.0));
  frame_numbers_.push_back(timings->frame_number);

  const size_t frame = frame_ms_.size();
  for (size_t p = 0; p < timings->pass_ms.size(); ++p) {
    const std::string& name = timings->plan->passes[p].name;
    auto found = std::find_if(passes_.begin(), passes_.end(),
                              [&](const PassSamples& samples) { return samples.name == name; });
    if (found == passes_.end()) found = passes_.insert(passes_.end(), {name, {}});
    // A pass absent from earlier frames counts as 0 there, so every series has one value per frame.
    found->ms.resize(frame, 0.0);
    found->ms.back() += timings->pass_ms[p];
  }
  return true;
}

std::vector<PassTime> GpuTimeLog::pass_summaries(size_t first) const {
  std::vector<PassTime> summaries;
  for (const PassSamples& pass : passes_) {
    std::vector<double> samples = pass.ms;
    samples.resize(frame_ms_.size(), 0.0);
    samples.erase(samples.begin(), samples.begin() + std::ptrdiff_t(std::min(first, samples.size())));
    if (const auto summary = summarize(samples)) summaries.push_back({pass.name, *summary});
  }
  return summaries;
}

}  // namespace sg
