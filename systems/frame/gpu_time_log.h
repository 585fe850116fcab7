// SPDX-License-Identifier: MIT
#pragma once
// Collects the executor's per-pass GPU timings over a run, for the summary and --stats.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rendergraph/vulkan/graph_executor.h"
#include "systems/frame/time_summary.h"

namespace sg {

class GpuTimeLog {
 public:
  // Takes the timings of a completed frame; the same frame offered twice counts once. Whether
  // they were a frame not logged before.
  bool add(const std::optional<vk::FrameTimings>& timings);

  // Sum of a frame's passes, per logged frame.
  const std::vector<double>& frame_ms() const { return frame_ms_; }
  // Per logged frame, its frame number (vk::FrameTimings::frame_number).
  const std::vector<uint64_t>& frame_numbers() const { return frame_numbers_; }
  // One entry per pass name, in the order passes first appeared; passes that share a name (one
  // per light) are summed per frame. Over the logged frames from `first` on.
  std::vector<PassTime> pass_summaries(size_t first = 0) const;

 private:
  struct PassSamples {
    std::string name;
    std::vector<double> ms;
  };
  std::optional<uint64_t> last_frame_;
  std::vector<double> frame_ms_;
  std::vector<uint64_t> frame_numbers_;
  std::vector<PassSamples> passes_;
};

}  // namespace sg
