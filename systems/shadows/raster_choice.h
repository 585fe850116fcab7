// SPDX-License-Identifier: MIT
#pragma once
// How --shadow-raster auto picks each GPU frame's raster: from the GPU time of the shadow passes
// that recent frames measured with each raster, per view drawn; from raster_for_views's model
// until both have been measured. The model misjudged near and dense frames by 2.4 to 4.7 times
// (H200, 2026-12-02, docs/PERFORMANCE.md "Near and dense lights, each raster"): what a frame's
// tiles hold, not their texels, sets the compute raster's cost, and measured times follow it.
//
// A raster is measured again (two frames drawn with it) when it never was (after
// `first_probe_gap` frames), or when this frame's views are more than twice or less than half
// those it was last measured at (at most once every `probe_gap` frames), so that a scene that
// changed is noticed without a slow frame every few.
//
// The first frame after a change of raster is not measured: the compute raster's static layers
// are not kept by the hardware one, so that frame redraws every caster where the next draws the
// moving ones only. Measured, a probe of the compute raster after hardware frames looked like its
// cold frame: with a sun of three 1024-texel cascades and 64 lights at eye height (H200,
// 2026-12-02) the hardware raster stayed, 4.48 ms of shadow passes against compute's 1.17.
//
// Neither a probe's frames nor a change's first frame tell what the frames to come cost (steady()
// is false for them): the shadow time budget does not learn from them. At 4,096 lights the
// hardware raster's probe took 59 and 70 ms of shadow passes where the compute raster takes 1.4
// to 2.9 (H100, 2026-12-06), and the budget, deciding on them, lowered 670 lights' maps 1.75
// tiers for the next 100 frames.
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
  // Whether the last choose() kept the frame before's raster and was not a probe of the other.
  bool steady() const { return steady_; }

 private:
  struct Cost {
    bool known = false;
    double ms_per_view = 0.0;  // an average over recent frames
    uint32_t views = 0;        // of the last frame measured
    uint32_t unsettled = 0;    // measurements to come of frames drawn just after a change to it
  };
  Cost& cost(ShadowRaster raster) { return costs_[raster == ShadowRaster::compute ? 1 : 0]; }
  ShadowRaster pick(uint32_t views, uint64_t large_tile_texels);
  std::array<Cost, 2> costs_;  // hardware, compute
  uint64_t frame_ = 0;
  uint64_t last_probe_ = 0;
  ShadowRaster last_ = ShadowRaster::automatic;     // the last frame's raster
  ShadowRaster probing_ = ShadowRaster::automatic;  // a probe's raster, for its second frame
  bool steady_ = true;
};

}  // namespace sg::shadows
