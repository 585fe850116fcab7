// SPDX-License-Identifier: MIT
#include "sandbox/run_stats.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "shadowgraph/version.h"

namespace sg::sandbox {
namespace {

// Ordered, so the file reads in the order run_stats.h documents.
using Json = nlohmann::ordered_json;

Json summary_json(const std::optional<TimeSummary>& summary) {
  if (!summary) return nullptr;
  return {{"median", summary->median}, {"min", summary->min}, {"max", summary->max}};
}

Json schedule_steps_json(const RunStats& stats) {
  Json steps = Json::object();
  for (size_t step = 0; step < shadows::schedule_step_count; ++step) {
    steps[shadows::schedule_step_names[step]] = summary_json(stats.schedule_steps_ms[step]);
  }
  return steps;
}

Json setting_json(const RunStats::EchoedSetting& setting) {
  if (!setting.value) return nullptr;
  switch (setting.type) {
    case SettingType::flag: return *setting.value == "true";
    case SettingType::whole: return std::stoull(*setting.value);
    case SettingType::number: return std::stod(*setting.value);
    case SettingType::choice:
    case SettingType::text: return *setting.value;
  }
  return *setting.value;
}

Json pipelines_json(const std::optional<std::vector<vk::PipelineExecutable>>& pipelines) {
  if (!pipelines) return nullptr;
  Json list = Json::array();
  for (const vk::PipelineExecutable& executable : *pipelines) {
    Json statistics = Json::object();
    for (const vk::PipelineStatistic& statistic : executable.statistics)
      statistics[statistic.name] = statistic.value;
    list.push_back(
        {{"pipeline", executable.pipeline}, {"executable", executable.name}, {"statistics", statistics}});
  }
  return list;
}

// The budget that held the most frames down; time on a tie.
const char* bound_most(const RunStats::ShadowBudget& budget) {
  if (budget.frames_bound_by_time == 0 && budget.frames_bound_by_memory == 0) return "none";
  return budget.frames_bound_by_time >= budget.frames_bound_by_memory ? "time" : "memory";
}

Json shadow_budget_json(const RunStats::ShadowBudget& budget) {
  return {
      {"budget_ms", budget.budget_ms ? Json(*budget.budget_ms) : Json()},
      {"measured_ms", summary_json(budget.measured_ms)},
      {"bound", bound_most(budget)},
      {"frames_bound", {{"time", budget.frames_bound_by_time}, {"memory", budget.frames_bound_by_memory}}},
      {"lights_demoted_by_time", summary_json(budget.lights_demoted_by_time)},
      {"views_deferred_by_time", summary_json(budget.views_deferred_by_time)},
      {"lights_demoted_by_memory", summary_json(budget.lights_demoted_by_memory)},
      {"lights_dropped_by_memory", summary_json(budget.lights_dropped_by_memory)},
      {"lowered_tiers", budget.lowered_tiers},
      {"view_cap", budget.view_cap ? Json(*budget.view_cap) : Json()}};
}

Json passes_json(const std::vector<PassTime>& passes) {
  Json json = Json::array();
  for (const PassTime& pass : passes)
    json.push_back({{"name", pass.name}, {"gpu_ms", summary_json(pass.gpu_ms)}});
  return json;
}

Json settled_json(const std::optional<RunStats::Settled>& settled) {
  if (!settled) return Json();
  return {{"from_frame", settled->from_frame},
          {"frames", settled->frames},
          {"cpu_frame_ms", summary_json(settled->cpu_frame_ms)},
          {"wall_frame_ms", summary_json(settled->wall_frame_ms)},
          {"gpu_frame_ms", summary_json(settled->gpu_frame_ms)},
          {"passes", passes_json(settled->passes)}};
}

Json stats_json(const RunStats& stats) {
  const scene::SceneStats& scene = stats.scene;
  const RunStats::Shadows& shadows = stats.shadows;
  Json maps = Json::array();
  for (const RunStats::Shadows::Map& map : shadows.maps) {
    maps.push_back({{"name", map.name},
                    {"resolution", map.resolution},
                    {"bytes", map.bytes},
                    {"frames_since_drawn", map.frames_since_drawn},
                    {"update", map.update},
                    {"priority", map.priority}});
  }
  Json per_resolution = Json::object();
  for (const auto& [resolution, lights] : shadows.lights_per_resolution) {
    per_resolution[std::to_string(resolution)] = lights;
  }
  Json settings = Json::object();
  for (const RunStats::EchoedSetting& setting : stats.settings)
    settings[setting.name] = setting_json(setting);
  return {{"schema_version", stats_schema_version},
          {"generator", "Shadowgraph " SHADOWGRAPH_VERSION},
          {"device", stats.device},
          {"resolution", {{"width", stats.width}, {"height", stats.height}}},
          {"scene_resolution", {{"width", stats.scene_width}, {"height", stats.scene_height}}},
          {"render_scale_changes", stats.render_scale_changes},
          {"frames", stats.frames},
          {"interrupted", stats.interrupted},
          {"scene",
           {{"name", stats.scene_name},
            {"triangles", scene.triangles},
            {"entities", scene.entities},
            {"mesh_instances", scene.mesh_instances},
            {"lights",
             {{"point", scene.point_lights},
              {"spot", scene.spot_lights},
              {"directional", scene.directional_lights},
              {"cylinder", scene.cylinder_lights},
              {"shadow_casting", scene.shadow_casting_lights}}}}},
          {"cpu_frame_ms", summary_json(stats.cpu_frame_ms)},
          {"cpu_phases_ms",
           {{"update", summary_json(stats.cpu_phases_ms.update)},
            {"gather", summary_json(stats.cpu_phases_ms.gather)},
            {"prepare", summary_json(stats.cpu_phases_ms.prepare)},
            {"declare", summary_json(stats.cpu_phases_ms.declare)},
            {"execute", summary_json(stats.cpu_phases_ms.execute)},
            {"gather_instances", summary_json(stats.cpu_phases_ms.instances)},
            {"gather_lights", summary_json(stats.cpu_phases_ms.lights)},
            {"prepare_schedule", summary_json(stats.cpu_phases_ms.schedule)},
            {"prepare_upload", summary_json(stats.cpu_phases_ms.upload)},
            {"prepare_views", summary_json(stats.cpu_phases_ms.views)}}},
          {"schedule_steps_ms", schedule_steps_json(stats)},
          {"wall_frame_ms", summary_json(stats.wall_frame_ms)},
          {"lighting", stats.lighting},
          {"gpu_frame_ms", summary_json(stats.gpu_frame_ms)},
          {"passes", passes_json(stats.passes)},
          {"settled", settled_json(stats.settled)},
          {"validation_errors", stats.validation_errors ? Json(*stats.validation_errors) : Json()},
          {"shadow_map_bytes", stats.shadow_map_bytes},
          {"dropped_light_pairs", stats.dropped_light_pairs},
          {"light_tiles_cut", stats.light_tiles_cut},
          {"light_list_pairs", summary_json(stats.light_list_pairs)},
          {"contact_shadows_skipped", stats.contact_shadows_skipped},
          {"filtered_shadows", stats.filtered_shadows},
          {"shadows",
           {{"views", shadows.views},
            {"raster", shadows.raster ? Json(*shadows.raster) : Json()},
            {"comparison_filter", shadows.comparison_filter},
            {"budget_bytes", shadows.budget_bytes},
            {"page_size", shadows.page_size},
            {"pages", shadows.pages},
            {"used_bytes", shadows.used_bytes},
            {"lights_per_resolution", per_resolution},
            {"lights_without_shadow", shadows.lights_without_shadow},
            {"lights_waiting", shadows.lights_waiting},
            {"cascades", shadows.cascades},
            {"views_rendered", summary_json(shadows.views_rendered)},
            {"views_cached", summary_json(shadows.views_cached)},
            {"views_moving_only", summary_json(shadows.views_moving_only)},
            {"map_lag_frames",
             {{"p50", summary_json(shadows.map_lag_p50)},
              {"p99", summary_json(shadows.map_lag_p99)},
              {"max", summary_json(shadows.map_lag_max)}}},
            {"lights_changed_tier", summary_json(shadows.lights_changed_tier)},
            {"lights_retiled", summary_json(shadows.lights_retiled)},
            {"atlas_repacks", shadows.atlas_repacks},
            {"maps", {{"total", shadows.maps_total}, {"largest", maps}}},
            {"caster_draws", shadows.caster_draws}}},
          {"shadow_budget", shadow_budget_json(stats.shadow_budget)},
          {"pipelines", pipelines_json(stats.pipelines)},
          {"settings", settings}};
}

}  // namespace

void write_stats_json(const std::string& path, const RunStats& stats) {
  const std::string text = stats_json(stats).dump(2) + "\n";
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) {
    throw std::runtime_error("cannot write stats to \"" + path + "\": " + std::strerror(errno));
  }
  file << text;
  file.close();
  // A full disk shows only when the buffered text is flushed.
  if (!file) {
    throw std::runtime_error("cannot write stats to \"" + path + "\": writing failed (" +
                             std::strerror(errno) + ")");
  }
}

}  // namespace sg::sandbox
