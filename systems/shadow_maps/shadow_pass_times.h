// SPDX-License-Identifier: MIT
#pragma once
// A timed frame's shadow work, read from its passes' GPU timestamps: every pass named "shadow
// ..." is shadow work (the batch's passes, or the per-light path's "shadow map ..." passes), and
// the batch's raster pass says which raster drew ("shadow raster": compute, "shadow views": the
// hardware). The automatic raster choice (ShadowViewBatch) and the time budget
// (shadows::ShadowTimeBudget) both learn from it.
#include <optional>

#include "rendergraph/device/fwd.h"
#include "systems/shadows/shadow_view_path.h"

namespace sg {

struct ShadowPassTimes {
  double ms = 0.0;                              // every shadow pass of the frame, summed
  std::optional<shadows::ShadowRaster> raster;  // the batch's raster; unset on the per-light path
};

ShadowPassTimes shadow_pass_times(const vk::FrameTimings& timings);

}  // namespace sg
