// SPDX-License-Identifier: MIT
#pragma once
// How the renderer draws a frame: plain data, set from the command line through the settings table
// (systems/frame/frame_settings.h) or by code.
#include <cstdint>
#include <optional>

#include "systems/lighting/lighting_path.h"
#include "systems/shadows/cube_shadow_mode.h"
#include "systems/shadows/frame_lights.h"
#include "systems/shadows/shadow_resolution.h"
#include "systems/shadows/shadow_time_policy.h"
#include "systems/shadows/shadow_view_path.h"

namespace sg {

// The time budget for shadows on GPUs unless set: a third of a 60 Hz frame (16.7 ms). On H200
// frames with a thousand moving lights near the camera took 15 to 60 ms of shadow passes.
inline constexpr float default_gpu_shadow_budget_ms = 6.0f;

// At each pixel the lights that run their filter kernels unless set (GPUs); the rest take the hard
// test (TiledLightingPass). H200, 1920x1080, 1,024 lights on a sixteenth of the stress hall
// (2026-12-02): lighting 10.1 ms with every light filtering, 5.0 with 8, 4.4 with 4; pictures
// 1.3% of pixels more than 2 levels apart with 8 (docs/PERFORMANCE.md).
inline constexpr uint32_t default_gpu_filtered_lights = 8;

struct RendererSettings {
  shadows::LightOverrides lights;
  shadows::CubeShadowMode cube_shadows = shadows::CubeShadowMode::layered;
  LightingPath lighting = LightingPath::automatic;
  LitSumStart lit_sum_start = LitSumStart::automatic;        // the deferred path's
  LightRecordsIn light_records = LightRecordsIn::automatic;  // the deferred path's
  // Deferred lighting where the culling runs an invocation per tile (CPU devices): tiles whose
  // light groups are one of the frame's group sets take one pass for them all (TiledLightingPass).
  bool group_sets = true;
  PipelineBuilds pipeline_builds = PipelineBuilds::background;  // the group sets' pipelines
  bool cull_casters = true;  // off: every shadow view draws every caster (the naive baseline)
  // Batched falls back to per-light where the device cannot draw views into atlas layers at once.
  shadows::ShadowViewPath shadow_views = shadows::ShadowViewPath::batched;
  shadows::ShadowRaster shadow_raster = shadows::ShadowRaster::automatic;  // the batched path's
  shadows::ShadowResolution shadow_resolution = shadows::ShadowResolution::screen;
  uint32_t shadow_memory_mib = 0;  // the atlas's budget; 0: the device's default
  uint32_t shadow_view_budget = shadows::default_shadow_view_budget;  // views redrawn a frame; 0: all due
  // The shadow passes' GPU time a frame may take (shadows::ShadowTimeBudget); 0: no budget; unset:
  // default_gpu_shadow_budget_ms on GPUs, none on CPU devices (lavapipe), whose shadow passes
  // always take far longer and would lose resolution in every picture.
  std::optional<float> shadow_budget_ms;
  // How the time budget's lowered resolutions fall on the lights (shadows::ShadowTimePolicy).
  shadows::ShadowTimePolicy shadow_time_policy = shadows::ShadowTimePolicy::redraw_cost;
  // Deferred lighting: at each pixel, the most lights that run their own shadow filter kernels,
  // the heaviest there; lighter lights take the hard test. 0: every light filters; unset:
  // default_gpu_filtered_lights on GPUs, every light on CPU devices.
  std::optional<uint32_t> filtered_lights;
  bool cache_shadows = true;  // off: every map is redrawn every frame (within the view budget)
  // Where the compute raster may run: keep a static layer per map (ShadowViewBatch), so that maps
  // wrong only through moving casters redraw just those.
  bool static_shadow_layers = true;
  float exposure = 1.0f;  // multiplies the lit sum before tone mapping
  // The ambient term kA * IA per channel, linear RGB (docs/ALGORITHMS.md 2.6): what a surface
  // reflects of its base color where no light reaches.
  glm::vec3 ambient{0.15f};
  LightingView view = LightingView::lit;
  // Threads that run a frame's CPU work split in pieces, the calling thread included; 0: one per
  // hardware thread.
  uint32_t cpu_threads = 0;
};

// `settings` turned into the source documents' frame, the baseline to measure against (--naive): a
// pass per shadow view and six per cube, every map every frame, every caster in every view, no
// time budget, forward lighting of every light at every pixel.
RendererSettings naive_baseline(RendererSettings settings);

}  // namespace sg
