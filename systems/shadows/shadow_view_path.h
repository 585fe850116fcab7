// SPDX-License-Identifier: MIT
#pragma once
#include <cstdint>

#include "systems/scene/enum_names.h"

namespace sg::shadows {

// How the shadow views due in a frame are drawn: all at once, culled and batched on the GPU
// (ShadowViewBatch, needs shaderOutputLayer), or one render-graph pass per light with casters
// culled on the CPU (ShadowPasses), the baseline.
enum class ShadowViewPath { batched, per_light };
constexpr EnumNames<ShadowViewPath, 2> enum_names(ShadowViewPath) {
  return {{{ShadowViewPath::batched, "batched"}, {ShadowViewPath::per_light, "per-light"}}};
}

// How the batched path rasterizes the views: with the raster hardware (one multi-draw indirect
// pass), or in compute (shaders/shadow_raster.comp), which is faster where the hardware sets up
// the small views' triangles slowly. automatic: on CPU devices the hardware; on GPUs chosen each
// frame by RasterChoice (raster_choice.h) from measured times, raster_for_views until both
// rasters have been measured (docs/PERFORMANCE.md).
enum class ShadowRaster { automatic, hardware, compute };
constexpr EnumNames<ShadowRaster, 3> enum_names(ShadowRaster) {
  return {{{ShadowRaster::automatic, "auto"},
           {ShadowRaster::hardware, "hardware"},
           {ShadowRaster::compute, "compute"}}};
}

// automatic's choice on a GPU for a frame's due `views`, `large_tile_texels` the area of those
// of large_tile texels a side or more: whichever a cost model fitted to the H200 on 2026-11-30
// predicts is cheaper (docs/PERFORMANCE.md). The raster hardware pays about 13 us a view, for setting up
// small views' triangles, plus 0.5 ms; compute about 2 us a view, plus 2.5 ns a texel of large tiles, whose
// large triangles a workgroup per caster and view fills slowly (one 2048-texel spot map of 54k triangles
// took 7.1 ms in compute, 0.34 ms on the hardware).
inline constexpr std::uint32_t large_tile = 512;
inline ShadowRaster raster_for_views(std::uint32_t views, std::uint64_t large_tile_texels) {
  const double hardware_ms = 0.5 + 0.013 * views;
  const double compute_ms = 0.002 * views + 2.5e-6 * double(large_tile_texels);
  return hardware_ms < compute_ms ? ShadowRaster::hardware : ShadowRaster::compute;
}

// The default budget of views (2D maps and cube faces) re-rendered in one frame.
inline constexpr unsigned default_shadow_view_budget = 4096;

}  // namespace sg::shadows
