// SPDX-License-Identifier: MIT
#include "systems/shadows/raster_choice.h"

#include <utility>

namespace sg::shadows {

ShadowRaster RasterChoice::choose(uint32_t views, uint64_t large_tile_texels) {
  ++frame_;
  steady_ = true;
  if (views == 0) return raster_for_views(views, large_tile_texels);    // not measured
  const bool probe_second_frame = probing_ != ShadowRaster::automatic;  // pick() draws it
  const ShadowRaster chosen = pick(views, large_tile_texels);
  // A probe's first frame changes the raster, its second keeps it.
  steady_ = chosen == last_ && !probe_second_frame;
  if (chosen != last_) ++cost(chosen).unsettled;
  last_ = chosen;
  return chosen;
}

ShadowRaster RasterChoice::pick(uint32_t views, uint64_t large_tile_texels) {
  if (probing_ != ShadowRaster::automatic) return std::exchange(probing_, ShadowRaster::automatic);
  const ShadowRaster model = raster_for_views(views, large_tile_texels);
  for (const ShadowRaster raster :
       {model, model == ShadowRaster::compute ? ShadowRaster::hardware : ShadowRaster::compute}) {
    const Cost& c = cost(raster);
    const bool stale = !c.known || views > 2 * uint64_t{c.views} || 2 * uint64_t{views} < c.views;
    if (stale && frame_ - last_probe_ >= (c.known ? probe_gap : first_probe_gap)) {
      last_probe_ = frame_;
      if (raster != last_) probing_ = raster;  // its first frame is not measured: draw a second
      return raster;
    }
  }
  const Cost& hardware = cost(ShadowRaster::hardware);
  const Cost& compute = cost(ShadowRaster::compute);
  if (!hardware.known || !compute.known) return model;
  return hardware.ms_per_view < compute.ms_per_view ? ShadowRaster::hardware : ShadowRaster::compute;
}

void RasterChoice::measured(ShadowRaster raster, uint32_t views, double ms) {
  if (views == 0 || raster == ShadowRaster::automatic) return;
  Cost& c = cost(raster);
  if (c.unsettled > 0) {
    --c.unsettled;
    return;
  }
  const double per_view = ms / views;
  // Frames of one scene vary (moving lights, the cache's choice of views): an average of recent
  // ones, the newest weighing a quarter. A frame of twice or half the views is another scene,
  // whose cost per view replaces the old one.
  const bool alike = c.known && views <= 2 * uint64_t{c.views} && 2 * uint64_t{views} >= c.views;
  c.ms_per_view = alike ? 0.75 * c.ms_per_view + 0.25 * per_view : per_view;
  c.views = views;
  c.known = true;
}

}  // namespace sg::shadows
