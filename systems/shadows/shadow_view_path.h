#pragma once

namespace sg::shadows {

// How the shadow views due in a frame are drawn: all at once, culled and batched on the GPU
// (ShadowViewBatch, needs shaderOutputLayer), or one render-graph pass per light with casters
// culled on the CPU (ShadowPasses), the baseline.
enum class ShadowViewPath { batched, per_light };

// The default budget of views (2D maps and cube faces) re-rendered in one frame.
inline constexpr unsigned default_shadow_view_budget = 4096;

}  // namespace sg::shadows
