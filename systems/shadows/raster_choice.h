// SPDX-License-Identifier: MIT
#pragma once
// How --shadow-raster auto picks each GPU frame's raster: from the GPU time of the shadow passes
// that recent frames measured with each raster, per view drawn; from raster_for_views's model
// until both have been measured. The model misjudged near and dense frames by 2.4 to 4.7 times
// (H200, 2026-12-02, docs/PERFORMANCE.md "Near and dense lights, each raster"): what a frame's
// tiles hold, not their texels, sets the compute raster's cost, and measured times follow it.
//
// A raster is measured again (one frame drawn with it) when it never was (after
// `first_probe_gap` frames), or when this frame's views are more than twice or less than half
// those it was last measured at (at most once every `probe_gap` frames), so that a scene that
// changed is noticed without a slow frame every few.
#include <array>
#include <cstdint>

#include "systems/shadows/shadow_view_path.h"

namespace sg::shadows {

class RasterChoice {
 public:
  static constexpr uint64_t probe_gap = 120;
  // A raster never measured is tried sooner: a few frames, for the first measurement to come back.
  static constexpr uint64_t first_probe_gap = 8;

  // The raster for a frame of `views` views, `large_tile_texels` as raster_for_views takes them.
  ShadowRaster choose(uint32_t views, uint64_t large_tile_texels);
  // A frame drawn with `raster` (hardware or compute) for `views` views took `ms` of shadow passes.
  void measured(ShadowRaster raster, uint32_t views, double ms);

 private:
  struct Cost {
    bool known = false;
    double ms_per_view = 0.0;  // an average over recent frames
    uint32_t views = 0;        // of the last frame measured
  };
  Cost& cost(ShadowRaster raster) { return costs_[raster == ShadowRaster::compute ? 1 : 0]; }
  std::array<Cost, 2> costs_;  // hardware, compute
  uint64_t frame_ = 0;
  uint64_t last_probe_ = 0;
};

}  // namespace sg::shadows
