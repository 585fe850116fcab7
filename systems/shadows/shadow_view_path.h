#pragma once

namespace sg::shadows {

// How the shadow views due in a frame are drawn: all at once, culled and batched on the GPU
// (ShadowViewBatch, needs shaderOutputLayer), or one render-graph pass per light with casters
// culled on the CPU (ShadowPasses), the baseline.
enum class ShadowViewPath { batched, per_light };

// How the batched path rasterizes the views: with the raster hardware (one multi-draw indirect
// pass), or in compute (shaders/shadow_raster.comp), which is faster where the hardware sets up
// the small views' triangles slowly. automatic: compute on GPUs, hardware on CPU devices
// (measured in docs/PERFORMANCE.md).
enum class ShadowRaster { automatic, hardware, compute };

// The default budget of views (2D maps and cube faces) re-rendered in one frame.
inline constexpr unsigned default_shadow_view_budget = 4096;

}  // namespace sg::shadows
