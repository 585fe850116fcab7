// SPDX-License-Identifier: MIT
#pragma once
// Machine-readable facts about one sandbox run, written by --stats as JSON.
//
// The JSON keys are a contract for scripts and benchmarks: later versions add keys but never
// rename or remove these without raising schema_version (stats_schema_version). Times are
// milliseconds; sizes are bytes.
//
// {
//   "schema_version": 1,                         // the form of this file (stats_schema_version)
//   "generator": "Shadowgraph 0.1.0",            // the engine that wrote it
//   "device": "NVIDIA H100 ...",                 // the Vulkan device's name
//   "resolution": {"width": 1280, "height": 720},
//   "scene_resolution": {"width": 640, "height": 360},  // what the scene was drawn at, scaled up
//                                                // to "resolution" (--render-scale)
//   "render_scale_changes": 0,                   // how often a CPU device's window changed its
//                                                // render scale to the frame time (the last
//                                                // one is scene_resolution's)
//   "frames": 3,                                 // frames rendered
//   "interrupted": false,                        // a signal (Ctrl-C) ended the run early: the
//                                                // figures are of the frames before it
//   "scene": {
//     "name": "default",                         // built-in name or the file path
//     "triangles": 1234, "entities": 56, "mesh_instances": 20,
//     "lights": {"point": 2, "spot": 2, "directional": 1, "cylinder": 1, "shadow_casting": 6}
//   },
//   "cpu_frame_ms": {"median": 1.5, "min": 1.2, "max": 3.0},  // null when no frame ran; CPU
//                                                // time per frame without waits for the GPU
//   "cpu_phases_ms": {"update": {...}, "gather": {...}, "prepare": {...}, "declare": {...},
//                     "execute": {...},          // the CPU frame by phase (Frame::record)
//                     "gather_instances": {...}, "gather_lights": {...},  // within gather
//                     "prepare_schedule": {...}, "prepare_upload": {...},  // within prepare
//                     "prepare_views": {...}},
//   "schedule_steps_ms": {"views": {...}, "requests": {...}, "match": {...}, "budget": {...},
//                     "tiles": {...}, "placements": {...}, "dirty": {...}, "casters": {...},
//                     "choose": {...}, "renders": {...}, "apply": {...}},  // within
//                                                // prepare_schedule: the shadow schedule's steps
//                                                // (systems/shadows/schedule_steps.h)
//   "wall_frame_ms": {...},                      // elapsed time per frame, waits included:
//                                                // present to present in a window, frame start
//                                                // to frame start headless; null under 2 frames
//   "lighting": "deferred",                      // the lighting path used: forward, deferred
//   "gpu_frame_ms": {"median": ..., "min": ..., "max": ...},  // null without GPU timestamps
//   "passes": [{"name": "lighting", "gpu_ms": {"median": ..., "min": ..., "max": ...}}],
//   "settled": {"from_frame": 85, "frames": 315,   // the frames from the first in which no
//               "cpu_frame_ms": {...},           // shadowed light waited for its first map to
//               "wall_frame_ms": {...},          // the last, and their times as above: what a
//               "gpu_frame_ms": {...},           // longer run settles at, without the maps'
//               "passes": [...]},                // first fill; null when lights waited in
//                                                // every frame
//   "validation_errors": 0,                      // null when the validation layer was off
//   "shadow_map_bytes": 0,                       // GPU memory holding shadow maps (the atlas image)
//   "dropped_light_pairs": 0,                    // (tile, light) pairs the light lists' pool had
//                                                // no room for over the run: lights missing there
//   "light_tiles_cut": 0,                        // tiles whose lists a CPU driver's guard against
//                                                // endless loops cut short over the run: lights
//                                                // missing there
//   "light_list_pairs": {"median": ..., "min": ..., "max": ...},  // per frame: the (tile, light)
//                                                // pairs the opaque surfaces' light lists held,
//                                                // which lighting's cost follows, from the
//                                                // frames read back; null when lit without
//                                                // lists (fused)
//   "contact_shadows_skipped": 0,                // the last frame's lights whose contact shadows
//                                                // were not drawn (lit other than deferred)
//   "filtered_shadows": 8,                       // at each pixel the most lights that ran their
//                                                // shadow filters, the heaviest there; the rest
//                                                // took the hard test (--filtered-shadows); 0:
//                                                // every light filtered
//   "shadows": {
//     "views": "batched",                        // batched or per-light (--shadow-views)
//     "raster": "compute",                       // batched: compute or hardware; per-light: null
//     "comparison_filter": "linear",             // the 2D kernels' hardware taps: linear, each a
//                                                // bilinear 2x2; nearest where the device cannot
//                                                // filter the maps' depth format (harder edges)
//     "budget_bytes": 1073741824,                // the atlas's budget (--shadow-memory)
//     "page_size": 4096, "pages": 2,             // the atlas image: pages of page_size texels
//     "used_bytes": 12345678,                    // what the lights' tiles take, last frame
//     "lights_per_resolution": {"256": 10, "64": 200},  // last frame, per tile side
//     "lights_without_shadow": 0,                // last frame: out of sight or over the budget
//     "lights_waiting": 0,                       // last frame: have a tile, not drawn yet
//     "cascades": 3,                             // last frame: directional lights' cascaded maps
//                                                // in use; each counts as a light in the counts
//     "views_rendered": {"median": ..., "min": ..., "max": ...},  // per frame
//     "views_cached": {"median": ..., "min": ..., "max": ...},
//     "views_moving_only": {"median": ..., "min": ..., "max": ...},  // of views_rendered: moving
//                                                  // casters drawn alone over static layers
//     "map_lag_frames": {                        // per frame, over the lights whose maps were due
//                                                // (moved, casters moved, new): how many frames
//                                                // each map had been wrong, 0 if drawn that frame
//       "p50": {...}, "p99": {...}, "max": {...}},  // the frame's median, 99th percentile, most
//     "lights_changed_tier": {...},              // per frame: lights whose resolution changed
//     "lights_retiled": {...},                   // per frame: lights given other tiles (new,
//                                                // resized, or moved by a repack): maps drawn anew
//     "atlas_repacks": 0,                        // frames whose atlas placed every tile anew
//     "maps": {"total": 2, "largest": [          // the last frame's maps with a tile, the
//       {"name": "spot east", "resolution": 512, "bytes": 1048576, "frames_since_drawn": 0,
//        "update": "auto", "priority": 0.0}]},   // largest first, at most 1,024 listed
//     "caster_draws": 0                          // caster instances drawn into views, a late frame
//   },
//   "shadow_budget": {                           // what the two shadow budgets held down (README,
//                                                // "Lights and shadows"): memory (--shadow-memory,
//                                                // the atlas) and time (--shadow-budget-ms)
//     "budget_ms": 6.0,                          // the time budget in use; null: none (CPU
//                                                // devices' default, 0, --naive)
//     "measured_ms": {"median": ..., "min": ..., "max": ...},  // per timed frame: the shadow
//                                                // passes' GPU time; null without timestamps
//     "bound": "time",                           // the budget that held the most frames down:
//                                                // time, memory, or none when neither held any
//     "frames_bound": {"time": 120, "memory": 0},  // frames each held down (a frame may count
//                                                // for both); time: a light demoted or a view
//                                                // deferred, memory: a light demoted or dropped
//     "lights_demoted_by_time": {...},           // per frame: lights below the resolution their
//                                                // size on screen asks
//     "views_deferred_by_time": {...},           // per frame: views due, within --shadow-updates,
//                                                // left for later frames
//     "lights_demoted_by_memory": {...},         // per frame: lights below what they want
//     "lights_dropped_by_memory": {...},         // per frame: lights without shadow
//     "lowered_tiers": 1.25,                     // last frame: log2 of every light's resolution
//                                                // lowered by this much (never below its floor;
//                                                // less the tiers its redraw rate spares under
//                                                // --shadow-time-policy redraw-cost)
//     "view_cap": null                           // last frame: the time budget's cap on views
//                                                // redrawn; null: none
//   },
//   "pipelines": [                               // with --pipeline-statistics where the driver
//                                                // reports them, else null: every pipeline
//                                                // the engine built, in order (not the panels')
//     {"pipeline": "tiled lighting cube pcss", "executable": "Compute Shader",
//      "statistics": {"Register Count": 64, ...}}  // the driver's names and figures
//   ],
//   "settings": {"width": 1280, "lighting": "auto", "camera": null, "headless": true, ...}
//                                                // every option of the run by name (the
//                                                // settings tables): numbers, true/false for
//                                                // flags, text for the rest; null when unset
// }
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rendergraph/device/pipeline_statistics.h"
#include "systems/frame/setting.h"
#include "systems/frame/time_summary.h"
#include "systems/scene/scene_queries.h"
#include "systems/shadows/schedule_steps.h"

namespace sg::sandbox {

// --stats' form: raised when a key changes meaning or goes away; added keys keep it.
inline constexpr int stats_schema_version = 1;

struct RunStats {
  std::string device;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t scene_width = 0;  // Frame::scene_extent
  std::uint32_t scene_height = 0;
  std::uint32_t render_scale_changes = 0;  // SandboxFrame::render_scale_changes
  std::uint64_t frames = 0;
  bool interrupted = false;  // interrupt.h
  std::string scene_name;
  scene::SceneStats scene;  // scene::scene_stats of the rendered scene
  std::optional<TimeSummary> cpu_frame_ms;
  struct CpuPhases {
    std::optional<TimeSummary> update, gather, prepare, declare, execute;
    // Within gather and prepare (SceneRenderer::CpuSteps).
    std::optional<TimeSummary> instances, lights, schedule, upload, views;
  } cpu_phases_ms;
  // Within prepare_schedule: the shadow schedule's steps, by shadows::ScheduleStep.
  std::array<std::optional<TimeSummary>, shadows::schedule_step_count> schedule_steps_ms;
  std::optional<TimeSummary> wall_frame_ms;
  std::string lighting;
  std::optional<TimeSummary> gpu_frame_ms;  // unset when the device has no timestamps
  std::vector<PassTime> passes;             // in execution order
  // The same figures over the frames from the first in which no shadowed light waited for its
  // first map (Frame::first_maps) to the last; unset when some still waited in every frame.
  struct Settled {
    std::uint64_t from_frame = 0;  // counted from 0, the run's first frame
    std::uint64_t frames = 0;
    std::optional<TimeSummary> cpu_frame_ms, wall_frame_ms, gpu_frame_ms;
    std::vector<PassTime> passes;
  };
  std::optional<Settled> settled;
  // Unset when the validation layer was off: 0 would claim a check that never ran.
  std::optional<std::uint32_t> validation_errors;
  std::uint64_t shadow_map_bytes = 0;
  std::uint64_t dropped_light_pairs = 0;
  std::uint64_t light_tiles_cut = 0;
  std::optional<TimeSummary> light_list_pairs;  // counts, summarized like times
  std::uint32_t contact_shadows_skipped = 0;
  std::uint32_t filtered_shadows = 0;
  // Every setting's value as the command line writes it (Setting::get), in the table's order.
  struct EchoedSetting {
    std::string name;
    SettingType type = SettingType::text;
    std::optional<std::string> value;
  };
  std::vector<EchoedSetting> settings;

  struct Shadows {
    std::string views;
    std::optional<std::string> raster;
    std::string comparison_filter;  // linear or nearest
    std::uint64_t budget_bytes = 0;
    std::uint32_t page_size = 0;
    std::uint32_t pages = 0;
    std::uint64_t used_bytes = 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> lights_per_resolution;
    std::uint32_t lights_without_shadow = 0;
    std::uint32_t lights_waiting = 0;
    std::uint32_t cascades = 0;
    std::optional<TimeSummary> views_rendered;  // counts, summarized like times
    std::optional<TimeSummary> views_cached;
    std::optional<TimeSummary> views_moving_only;
    std::uint64_t caster_draws = 0;
    // Per frame (Frame::MapTimeline), counts summarized like times.
    std::optional<TimeSummary> map_lag_p50, map_lag_p99, map_lag_max, lights_changed_tier, lights_retiled;
    std::uint64_t atlas_repacks = 0;  // frames
    // The last frame's maps with a tile, the largest first, at most max_listed_maps of them.
    struct Map {
      std::string name;
      std::uint32_t resolution = 0;  // per face for cubes
      std::uint64_t bytes = 0;
      std::uint32_t frames_since_drawn = 0;
      std::string update;  // ShadowSettings::update
      float priority = 0.0f;
    };
    std::uint64_t maps_total = 0;
    std::vector<Map> maps;
  } shadows;
  static constexpr std::size_t max_listed_maps = 1024;

  struct ShadowBudget {
    std::optional<double> budget_ms;         // unset: no time budget
    std::optional<TimeSummary> measured_ms;  // per timed frame
    std::uint64_t frames_bound_by_time = 0;  // "bound" is the larger, "none" when both are 0
    std::uint64_t frames_bound_by_memory = 0;
    std::optional<TimeSummary> lights_demoted_by_time;  // per frame, counts summarized like times
    std::optional<TimeSummary> views_deferred_by_time;
    std::optional<TimeSummary> lights_demoted_by_memory;
    std::optional<TimeSummary> lights_dropped_by_memory;
    double lowered_tiers = 0.0;
    std::optional<std::uint32_t> view_cap;  // unset: none
  } shadow_budget;
  // Unset without --pipeline-statistics or where the driver reports none.
  std::optional<std::vector<vk::PipelineExecutable>> pipelines;
};

// Writes `stats` as the JSON above (indented, one trailing newline), replacing the file.
// Throws std::runtime_error naming the path and the reason when it cannot be written.
void write_stats_json(const std::string& path, const RunStats& stats);

}  // namespace sg::sandbox
