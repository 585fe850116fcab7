// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cstdio>
#include <exception>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rendergraph/device/context.h"
#include "rendergraph/device/readback.h"
#include "sandbox/run.h"
#include "sandbox/run_stats.h"
#include "sandbox/sandbox_frame.h"
#include "sandbox/shadow_map_dump.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/interrupt.h"
#include "systems/frame/png.h"
#include "systems/frame/scene_view.h"
#include "systems/scene/scene_queries.h"
#include "systems/shadows/shadow_atlas_shape.h"

namespace sg::sandbox {
namespace {

// The last frame's maps with a tile into `out`: the largest (then by name) first, at most
// RunStats::max_listed_maps of them, and how many there were.
void list_shadow_maps(const shadows::FrameLights& lights, RunStats::Shadows& out) {
  const auto row = [](const auto& view, uint32_t faces) {
    return RunStats::Shadows::Map{view.name,
                                  view.resolution,
                                  shadows::shadow_map_bytes(view.resolution, faces),
                                  view.frames_since_drawn,
                                  std::string(to_string(view.update)),
                                  view.priority};
  };
  out.maps.clear();
  for (const shadows::ShadowMapView& map : lights.maps) {
    if (map.resolution > 0) out.maps.push_back(row(map, 1));
  }
  for (const shadows::ShadowCubeView& cube : lights.cubes) {
    if (cube.resolution > 0) out.maps.push_back(row(cube, 6));
  }
  out.maps_total = out.maps.size();
  const auto larger = [](const RunStats::Shadows::Map& a, const RunStats::Shadows::Map& b) {
    return a.bytes != b.bytes ? a.bytes > b.bytes : a.name < b.name;
  };
  const size_t listed = std::min(out.maps.size(), RunStats::max_listed_maps);
  std::partial_sort(out.maps.begin(), out.maps.begin() + std::ptrdiff_t(listed), out.maps.end(), larger);
  out.maps.resize(listed);
}

// The run's figures over the frames from the first in which no shadowed light waited for its
// first map: until then the frames draw the maps' first fill and light the waiting lights without
// a shadow, and a median over a short run is mostly those frames. The run's frames are numbered
// as its frame ring numbers them, one per recorded frame, across scenes opened on the way.
std::optional<RunStats::Settled> settled_stats(const Frame& frame, const RunRecord& record) {
  const std::optional<uint64_t> first = frame.first_maps();
  if (!first || *first >= record.cpu_frame_ms.size()) return std::nullopt;
  const auto from_first = [&](std::span<const double> samples) {
    return summarize(samples.subspan(std::min(size_t(*first), samples.size())));
  };
  RunStats::Settled settled;
  settled.from_frame = *first;
  settled.frames = record.cpu_frame_ms.size() - *first;
  settled.cpu_frame_ms = from_first(record.cpu_frame_ms);
  settled.wall_frame_ms = from_first(record.wall_frame_ms);
  if (record.gpu_times) {
    const std::vector<uint64_t>& numbers = record.gpu_times->frame_numbers();
    const auto timed =
        static_cast<size_t>(std::lower_bound(numbers.begin(), numbers.end(), *first) - numbers.begin());
    settled.gpu_frame_ms = summarize(std::span(record.gpu_times->frame_ms()).subspan(timed));
    settled.passes = record.gpu_times->pass_summaries(timed);
  }
  return settled;
}

}  // namespace

int finish_run(const Options& options, vk::VulkanContext& context, const SceneView& scene,
               SandboxFrame& sandbox_frame, const RunRecord& record) {
  Frame& frame = sandbox_frame.frame();
  const bool rendered = !record.cpu_frame_ms.empty();
  if (interrupted()) {
    std::printf(
        "shadowgraph: interrupted after %zu frames: writing what they measured (a second Ctrl-C "
        "ends at once)\n",
        record.cpu_frame_ms.size());
  }
  // Each output is written whatever became of the ones before it, so that a screenshot the disk
  // refused does not cost the run's --stats as well; the failures end the program with 1.
  std::vector<std::string> failures;
  const auto write = [&failures](const auto& output) {
    try {
      output();
    } catch (const std::exception& error) {
      failures.emplace_back(error.what());
    }
  };
  if (!options.screenshot.empty() && !rendered) {
    std::printf("shadowgraph: no frame was rendered, so no screenshot was written\n");
  } else if (!options.screenshot.empty()) {
    write([&] {
      write_png(options.screenshot, vk::read_rgba8(context, frame.image()));
      std::printf("shadowgraph: wrote %s\n", options.screenshot.c_str());
    });
  }

  if (!options.export_gltf.empty()) write([&] { sandbox_frame.export_gltf(options.export_gltf); });

  if (!options.dump_shadow_maps.empty() && rendered) {
    write([&] { dump_shadow_maps(context, frame.renderer(), options.dump_shadow_maps); });
  }

  RunStats stats;
  stats.device = context.device_name();
  stats.width = frame.image().extent().width;
  stats.height = frame.image().extent().height;
  stats.scene_width = frame.scene_extent().width;
  stats.scene_height = frame.scene_extent().height;
  stats.render_scale_changes = sandbox_frame.render_scale_changes();
  stats.frames = record.cpu_frame_ms.size();
  stats.interrupted = interrupted();
  stats.scene_name = scene.scene.name;
  stats.scene = scene::scene_stats(scene.scene);
  stats.cpu_frame_ms = summarize(record.cpu_frame_ms);
  const Frame::PhaseTimes& phases = frame.phase_ms();
  stats.cpu_phases_ms = {summarize(phases.update),  summarize(phases.gather),   summarize(phases.prepare),
                         summarize(phases.declare), summarize(phases.execute),  summarize(phases.instances),
                         summarize(phases.lights),  summarize(phases.schedule), summarize(phases.upload),
                         summarize(phases.views)};
  for (size_t step = 0; step < shadows::schedule_step_count; ++step) {
    stats.schedule_steps_ms[step] = summarize(phases.schedule_steps[step]);
  }
  stats.wall_frame_ms = summarize(record.wall_frame_ms);
  stats.lighting = to_string(frame.renderer().lighting());
  if (record.gpu_times) {
    stats.gpu_frame_ms = summarize(record.gpu_times->frame_ms());
    stats.passes = record.gpu_times->pass_summaries();
  }
  stats.settled = settled_stats(frame, record);
  if (context.validation_enabled()) stats.validation_errors = context.validation_errors();
  if (const vk::PipelineStatisticsLog* log = context.pipeline_statistics()) {
    stats.pipelines = log->executables();
    std::printf("shadowgraph: statistics of %zu pipeline executables (--stats' \"pipelines\")\n",
                stats.pipelines->size());
  }
  const SceneRenderer& renderer = frame.renderer();
  const ShadowAtlas& atlas = renderer.shadow_atlas();
  const shadows::ShadowScheduleStats& schedule = renderer.shadow_stats();
  stats.shadow_map_bytes = atlas.bytes();
  stats.dropped_light_pairs = frame.take_dropped_light_pairs();
  if (stats.dropped_light_pairs > 0) {
    std::printf("shadowgraph: %llu (tile, light) pairs found no room in the light lists over the run\n",
                static_cast<unsigned long long>(stats.dropped_light_pairs));
  }
  stats.light_tiles_cut = renderer.light_tiles_cut();
  if (stats.light_tiles_cut > 0) {
    std::printf("shadowgraph: the CPU driver cut %llu tiles' light lists short over the run\n",
                static_cast<unsigned long long>(stats.light_tiles_cut));
  }
  stats.light_list_pairs = summarize(frame.light_list_pairs());
  stats.filtered_shadows = frame.renderer().filtered_lights();
  stats.contact_shadows_skipped = frame.renderer().contact_shadows_skipped();
  const std::optional<shadows::ShadowRaster> raster = renderer.shadow_raster();
  stats.shadows = {std::string(to_string(renderer.shadow_views())),
                   raster ? std::optional<std::string>(to_string(*raster)) : std::nullopt,
                   renderer.shadow_comparisons_filtered() ? "linear" : "nearest",
                   atlas.shape().budget_bytes,
                   atlas.shape().page_size,
                   atlas.pages(),
                   schedule.texels_used * atlas.texel_bytes(),
                   schedule.lights_per_resolution,
                   schedule.lights_without_shadow,
                   schedule.lights_waiting,
                   schedule.cascades,
                   summarize(frame.shadow_views_rendered()),
                   summarize(frame.shadow_views_cached()),
                   summarize(frame.shadow_views_moving_only()),
                   renderer.shadow_caster_draws()};
  list_shadow_maps(renderer.lights(), stats.shadows);
  const Frame::MapTimeline& timeline = frame.map_timeline();
  stats.shadows.map_lag_p50 = summarize(timeline.lag_p50);
  stats.shadows.map_lag_p99 = summarize(timeline.lag_p99);
  stats.shadows.map_lag_max = summarize(timeline.lag_max);
  stats.shadows.lights_changed_tier = summarize(timeline.lights_changed_tier);
  stats.shadows.lights_retiled = summarize(timeline.lights_retiled);
  stats.shadows.atlas_repacks = timeline.atlas_repacks;
  const Frame::ShadowBudgetRecord& budgets = frame.shadow_budget_record();
  const shadows::ShadowTimeBudget& time_budget = renderer.shadow_time_budget();
  const shadows::ShadowTimeBudget::Limits& limits = time_budget.limits();
  stats.shadow_budget = {time_budget.on() ? std::optional(time_budget.budget_ms()) : std::nullopt,
                         summarize(budgets.shadow_ms),
                         budgets.frames_bound_by_time,
                         budgets.frames_bound_by_memory,
                         summarize(budgets.lights_demoted_by_time),
                         summarize(budgets.views_deferred_by_time),
                         summarize(budgets.lights_demoted_by_memory),
                         summarize(budgets.lights_dropped_by_memory),
                         limits.lowered_tiers,
                         limits.view_cap != 0 ? std::optional(limits.view_cap) : std::nullopt};

  if (stats.cpu_frame_ms) {
    std::printf("shadowgraph: %llu frames, CPU frame time median %.2f ms (min %.2f, max %.2f)\n",
                static_cast<unsigned long long>(stats.frames), stats.cpu_frame_ms->median,
                stats.cpu_frame_ms->min, stats.cpu_frame_ms->max);
  }
  if (const RunStats::CpuPhases& p = stats.cpu_phases_ms; p.update) {
    std::printf(
        "shadowgraph: CPU frame by phase (medians): update %.2f, gather %.2f (instances %.2f, lights %.2f), "
        "prepare %.2f (schedule %.2f, upload %.2f, views %.2f), declare %.2f, execute %.2f ms\n",
        p.update->median, p.gather->median, p.instances->median, p.lights->median, p.prepare->median,
        p.schedule->median, p.upload->median, p.views->median, p.declare->median, p.execute->median);
  }
  // Where the schedule is a tenth of a millisecond or more (thousands of lights), its steps;
  // --stats has them always.
  if (const RunStats::CpuPhases& p = stats.cpu_phases_ms; p.schedule && p.schedule->median >= 0.1) {
    shadows::ScheduleStepTimes medians{};
    for (size_t step = 0; step < shadows::schedule_step_count; ++step) {
      medians[step] = stats.schedule_steps_ms[step]->median;
    }
    std::printf("shadowgraph: the shadow schedule's steps (medians): %s ms\n",
                shadows::schedule_steps_text(medians).c_str());
  }
  if (stats.wall_frame_ms) {
    std::printf("shadowgraph: wall time per frame median %.2f ms (min %.2f, max %.2f), %s lighting\n",
                stats.wall_frame_ms->median, stats.wall_frame_ms->min, stats.wall_frame_ms->max,
                stats.lighting.c_str());
  }
  if (stats.gpu_frame_ms) {
    std::printf("shadowgraph: GPU frame time median %.3f ms over %zu timed frames; per pass:",
                stats.gpu_frame_ms->median, record.gpu_times->frame_ms().size());
    // Hundreds of shadow passes would drown the line: past a few, they are summed.
    constexpr size_t listed_shadow_passes = 6;
    size_t shadow_passes = 0;
    double shadow_ms = 0.0;
    for (const PassTime& pass : stats.passes) {
      if (pass.name.rfind("shadow ", 0) == 0) {
        ++shadow_passes;
        shadow_ms += pass.gpu_ms.median;
      }
    }
    for (const PassTime& pass : stats.passes) {
      const bool shadow = pass.name.rfind("shadow ", 0) == 0;
      if (!shadow || shadow_passes <= listed_shadow_passes) {
        std::printf(" %s %.3f", pass.name.c_str(), pass.gpu_ms.median);
      }
    }
    if (shadow_passes > listed_shadow_passes) {
      std::printf(" (%zu shadow passes %.3f)", shadow_passes, shadow_ms);
    }
    std::printf("\n");
  }
  if (const std::optional<RunStats::Settled>& s = stats.settled; s && s->from_frame > 0 && s->cpu_frame_ms) {
    std::printf(
        "shadowgraph: every shadowed light had a map from frame %llu on; over the %llu frames since, "
        "CPU frame median %.2f ms",
        static_cast<unsigned long long>(s->from_frame), static_cast<unsigned long long>(s->frames),
        s->cpu_frame_ms->median);
    if (s->gpu_frame_ms) std::printf(", GPU frame median %.3f ms", s->gpu_frame_ms->median);
    std::printf(" (--stats: settled)\n");
  } else if (rendered && !s) {
    std::printf(
        "shadowgraph: %u lights waited for their first shadow map in every frame, the last included: every "
        "figure here is of the maps' first fill (run more frames, or raise --shadow-updates)\n",
        stats.shadows.lights_waiting);
  }
  if (stats.shadows.views_rendered) {
    const RunStats::Shadows& s = stats.shadows;
    constexpr double mib = 1 << 20;
    const std::string raster_note = s.raster ? ", " + *s.raster + " raster" : "";
    std::printf(
        "shadowgraph: shadows (%s views%s): atlas %u pages of %u (%.0f of %.0f MiB budget), tiles %.1f MiB;"
        " lights per resolution",
        s.views.c_str(), raster_note.c_str(), s.pages, s.page_size, double(stats.shadow_map_bytes) / mib,
        double(s.budget_bytes) / mib, double(s.used_bytes) / mib);
    for (const auto& [resolution, lights] : s.lights_per_resolution)
      std::printf(" %u:%u", resolution, lights);
    std::printf(
        "; %u without shadow, %u waiting, %u directional cascades; views per frame rendered %.0f (moving "
        "casters only %.0f), cached %.0f (medians); atlas repacked in %llu frames\n",
        s.lights_without_shadow, s.lights_waiting, s.cascades, s.views_rendered->median,
        s.views_moving_only->median, s.views_cached->median,
        static_cast<unsigned long long>(s.atlas_repacks));
  }
  if (const RunStats::ShadowBudget& b = stats.shadow_budget;
      b.lights_demoted_by_time && (b.budget_ms || b.frames_bound_by_memory > 0)) {
    std::printf("shadowgraph: shadow budgets: ");
    if (b.budget_ms) {
      std::printf("time %.2f ms", *b.budget_ms);
      if (b.measured_ms) std::printf(" (shadow passes median %.3f ms)", b.measured_ms->median);
      std::printf(
          " held %llu frames down (medians %.0f lights demoted, %.0f views deferred; last frame %.2f tiers "
          "lower",
          static_cast<unsigned long long>(b.frames_bound_by_time), b.lights_demoted_by_time->median,
          b.views_deferred_by_time->median, b.lowered_tiers);
      if (b.view_cap) std::printf(", at most %u views", *b.view_cap);
      std::printf(")");
    } else {
      std::printf("no time budget");
    }
    std::printf("; memory held %llu frames down (medians %.0f lights demoted, %.0f without shadow)\n",
                static_cast<unsigned long long>(b.frames_bound_by_memory), b.lights_demoted_by_memory->median,
                b.lights_dropped_by_memory->median);
  }
  const vk::MemoryStats memory = context.allocator().stats();
  std::printf("shadowgraph: GPU memory %.1f MiB used in %u blocks (%.1f MiB reserved)\n",
              double(memory.used_bytes) / (1 << 20), memory.block_count,
              double(memory.reserved_bytes) / (1 << 20));
  for (const Setting<Options>& setting : options_table()) {
    stats.settings.push_back({std::string(setting.info.name), setting.info.type, setting.get(options)});
  }
  if (!options.stats_path.empty()) {
    write([&] {
      write_stats_json(options.stats_path, stats);
      std::printf("shadowgraph: wrote %s\n", options.stats_path.c_str());
    });
  }
  for (const std::string& failure : failures)
    std::fprintf(stderr, "shadowgraph: error: %s\n", failure.c_str());
  if (stats.validation_errors) {
    std::printf("shadowgraph: validation errors: %u\n", *stats.validation_errors);
    if (*stats.validation_errors > 0) return 3;
  }
  if (!failures.empty()) return 1;
  return interrupted() ? 130 : 0;  // 128 + SIGINT, as shells report a run Ctrl-C ended
}

}  // namespace sg::sandbox
