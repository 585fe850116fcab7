// SPDX-License-Identifier: MIT
#pragma once
#include <cstdint>

#include "systems/scene/enum_names.h"

namespace sg {

// How the frame is lit, each light with its own algorithm (docs/PERFORMANCE.md says where each
// wins; tiled forward lighting won nowhere and is gone):
// - deferred: G-buffer, light culling, a compute pass per light group (each holding one
//   algorithm's code);
// - every_light: one forward pass with every light at every pixel (the --naive baseline);
// - fused: depth prepass, then one forward pass with every light at every pixel, holding only
//   the frame's light groups' code, that tone-maps into the frame: the fewest full-screen passes,
//   for a few lights on CPU devices;
// - automatic: on GPUs deferred; on CPU devices each frame cpu_lighting_for's choice
//   (SceneRenderer::lighting says which).
enum class LightingPath { automatic, deferred, every_light, fused };
constexpr EnumNames<LightingPath, 4> enum_names(LightingPath) {
  return {{{LightingPath::automatic, "auto"},
           {LightingPath::deferred, "deferred"},
           {LightingPath::every_light, "every light"},
           {LightingPath::fused, "fused"}}};
}

// automatic's choice on a CPU device for a frame of `lights` lights and `triangles` drawn: fused
// while its cost, every light at every pixel and the geometry drawn twice (depth prepass, then the
// forward pass), stays below deferred's, whose passes cost more but a pixel only its tile's lights
// and draw the geometry once; deferred where a light has contact shadows, which only it draws. On lavapipe at
// 1280x720 (2026-11-30), stress scene of 4.8k triangles with the sun, maps cached: 3 lights fused 23.4
// against deferred 41.9 ms a frame, 4 lights 42.5 against 50.1, 5 lights 70.6 against 53.9; the default scene
// (6 lights) about 250 against 200. With more geometry (2026-12-03, 3 lights): 10k triangles fused 49.8
// against 45.9, 25k 65.4 against 43.7, 50k 78.4 against 65.8; one light, point-room's 4.8k triangles 62
// against 78, spot-columns' 53.7k 175 against 94 (docs/PERFORMANCE.md): fused up to 8,192 triangles.
inline constexpr uint64_t max_fused_triangles = 8192;
constexpr LightingPath cpu_lighting_for(uint32_t lights, uint32_t contact_lights, uint64_t triangles) {
  return lights <= 4 && contact_lights == 0 && triangles <= max_fused_triangles ? LightingPath::fused
                                                                                : LightingPath::deferred;
}

// Where deferred lighting's lit sum starts (the ambient term times the base color, the background
// where no surface was drawn): a full-screen compute pass, or a third G-buffer target. The target
// costs the G-buffer more than the pass costs on GPUs with little raster hardware (H200, default
// scene, 1920x1080, 2026-11-30: +0.57 ms against 0.012) and less on lavapipe, whose compute passes store to
// images lane by lane (1280x720: +2.6 ms against 6.5).
// automatic: the G-buffer on CPU devices, the pass on GPUs.
enum class LitSumStart { automatic, pass, gbuffer };
constexpr EnumNames<LitSumStart, 3> enum_names(LitSumStart) {
  return {{{LitSumStart::automatic, "auto"}, {LitSumStart::pass, "pass"}, {LitSumStart::gbuffer, "gbuffer"}}};
}

// How deferred lighting's shaders read the light records (lights_interface.glsl). Through a
// uniform texel buffer, a record being 16-byte texels: llvmpipe fetches texels for all lanes at
// once, where it loads storage-buffer words lane by lane, one loop per load (lavapipe, default
// scene, 1280x720, 2026-12-03: 312-313 ms a frame against 764-765). Or from a storage buffer, the
// shaders' storage_records variants: a GPU's warp loads the record its lanes share once, where
// texel fetches take the texture units for every lane (H200, 1920x1080, 100,000 lights, the
// lighting passes: 26.6-26.7 -> 23.9-24.0 ms at eye height, 8.9 -> 7.6-7.7 from afar).
// automatic: the storage buffer on GPUs, the texel buffer on CPU devices. The other lighting
// paths read the texel buffer everywhere.
enum class LightRecordsIn { automatic, texel_buffer, storage_buffer };
constexpr EnumNames<LightRecordsIn, 3> enum_names(LightRecordsIn) {
  return {{{LightRecordsIn::automatic, "auto"},
           {LightRecordsIn::texel_buffer, "texel"},
           {LightRecordsIn::storage_buffer, "storage"}}};
}

// When a pipeline that a frame can do without (deferred lighting's group sets) is built:
// - background: on a thread of its own (vk::BackgroundPipelines), the frames doing without it until
//   it is ready, so that none waits for it (lavapipe, `default` scene: eight set pipelines took 16 s
//   to build, 2026-12-04). Which frame first takes it then depends on the build's speed;
// - in_frame: by the frame that first needs it, so that a run's pictures are the same every time.
enum class PipelineBuilds { background, in_frame };
constexpr EnumNames<PipelineBuilds, 2> enum_names(PipelineBuilds) {
  return {{{PipelineBuilds::background, "background"}, {PipelineBuilds::in_frame, "in-frame"}}};
}

// What the lighting writes: the lit picture, or the shadow-only debug view (white diffuse surfaces
// under white lights of the same intensities, shadows at full density, no ambient).
enum class LightingView : uint32_t { lit = 0, shadows = 1 };
constexpr EnumNames<LightingView, 2> enum_names(LightingView) {
  return {{{LightingView::lit, "lit"}, {LightingView::shadows, "shadows"}}};
}

}  // namespace sg
