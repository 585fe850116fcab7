// SPDX-License-Identifier: MIT
#pragma once
// A frame-rate cap for the window (--max-fps, the Frame panel's "max fps"): each frame starts no
// sooner than a period after the one before. A frame that came late is not made up for by a burst
// of short ones: the next starts a period after the late one.
#include <chrono>
#include <optional>

namespace sg::sandbox {

class FramePacer {
 public:
  using Clock = std::chrono::steady_clock;

  // 0: no cap.
  void set_max_fps(double fps) { max_fps_ = fps > 0.0 ? fps : 0.0; }
  double max_fps() const { return max_fps_; }

  // How long to wait, at `now`, before starting the next frame; the frame is taken to start when
  // that wait is over.
  Clock::duration wait(Clock::time_point now) {
    if (max_fps_ <= 0.0) {
      last_start_.reset();
      return Clock::duration::zero();
    }
    const auto period =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / max_fps_));
    const Clock::time_point start = last_start_ && *last_start_ + period > now ? *last_start_ + period : now;
    last_start_ = start;
    return start - now;
  }

 private:
  double max_fps_ = 0.0;
  std::optional<Clock::time_point> last_start_;
};

}  // namespace sg::sandbox
