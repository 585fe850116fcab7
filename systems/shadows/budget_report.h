// SPDX-License-Identifier: MIT
#pragma once
// When a budget's effect on the frames (lights demoted, views deferred, ...) is worth a log line:
// when it differs from what the last line said, and at most once every `interval` frames, so that
// an effect that changes every frame does not flood the log.
#include <cstdint>
#include <optional>
#include <utility>

namespace sg::shadows {

template <class Effect>
class BudgetReport {
 public:
  explicit BudgetReport(uint64_t interval) : interval_(interval) {}

  // The effect of frame number `frame`. When a line is due: the effect the last line reported
  // (the new line reports `effect`); else nullopt.
  std::optional<Effect> due(const Effect& effect, uint64_t frame) {
    if (effect == reported_) return std::nullopt;
    if (last_line_frame_ && frame - *last_line_frame_ < interval_) return std::nullopt;
    last_line_frame_ = frame;
    return std::exchange(reported_, effect);
  }

 private:
  uint64_t interval_;
  Effect reported_{};
  std::optional<uint64_t> last_line_frame_;
};

}  // namespace sg::shadows
