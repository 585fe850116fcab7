// SPDX-License-Identifier: MIT
// summarize() and the --stats JSON file.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sandbox/run_stats.h"
#include "shadowgraph/version.h"
#include "tests/support/gltf_writer.h"

namespace sg::sandbox {
namespace {

using scene::test::TempDir;

TEST(Summarize, OddCountTakesTheMiddleSample) {
  const std::vector<double> samples = {5.0, 1.0, 3.0, 9.0, 2.0};
  const std::optional<TimeSummary> summary = summarize(samples);
  ASSERT_TRUE(summary.has_value());
  EXPECT_EQ(summary->median, 3.0);
  EXPECT_EQ(summary->min, 1.0);
  EXPECT_EQ(summary->max, 9.0);
}

TEST(Summarize, EvenCountAveragesTheMiddlePair) {
  const std::vector<double> samples = {4.0, 1.0, 3.0, 2.0};
  const std::optional<TimeSummary> summary = summarize(samples);
  ASSERT_TRUE(summary.has_value());
  EXPECT_EQ(summary->median, 2.5);
  EXPECT_EQ(summary->min, 1.0);
  EXPECT_EQ(summary->max, 4.0);
}

TEST(Summarize, OneSampleAndNone) {
  const std::vector<double> one = {7.5};
  const std::optional<TimeSummary> summary = summarize(one);
  ASSERT_TRUE(summary.has_value());
  EXPECT_EQ(summary->median, 7.5);
  EXPECT_EQ(summary->min, 7.5);
  EXPECT_EQ(summary->max, 7.5);
  EXPECT_FALSE(summarize({}).has_value());
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream file(path);
  return nlohmann::json::parse(file);
}

void expect_summary(const nlohmann::json& json, const TimeSummary& expected) {
  ASSERT_TRUE(json.is_object()) << json.dump();
  EXPECT_EQ(json.size(), 3u) << json.dump();
  EXPECT_EQ(json.at("median").get<double>(), expected.median);
  EXPECT_EQ(json.at("min").get<double>(), expected.min);
  EXPECT_EQ(json.at("max").get<double>(), expected.max);
}

TEST(StatsJson, EveryFieldRoundTrips) {
  RunStats stats;
  stats.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
  stats.width = 640;
  stats.height = 360;
  stats.scene_width = 320;
  stats.scene_height = 180;
  stats.render_scale_changes = 3;
  stats.frames = 12;
  stats.interrupted = true;
  stats.scene_name = "stress";
  stats.scene.triangles = 250'123;
  stats.scene.entities = 4'321;
  stats.scene.mesh_instances = 1'234;
  stats.scene.point_lights = 32;
  stats.scene.spot_lights = 31;
  stats.scene.directional_lights = 1;
  stats.scene.cylinder_lights = 2;
  stats.scene.shadow_casting_lights = 60;
  stats.cpu_frame_ms = TimeSummary{1.5, 1.25, 3.75};
  stats.cpu_phases_ms = {TimeSummary{0.25, 0.125, 0.5},   TimeSummary{0.5, 0.25, 1.0},
                         TimeSummary{0.375, 0.25, 2.0},   TimeSummary{0.125, 0.0625, 0.25},
                         TimeSummary{0.25, 0.125, 0.5},   TimeSummary{0.125, 0.0625, 0.25},
                         TimeSummary{0.375, 0.25, 0.75},  TimeSummary{0.25, 0.125, 1.5},
                         TimeSummary{0.125, 0.0625, 0.5}, TimeSummary{0.0625, 0.03125, 0.125}};
  for (size_t step = 0; step < stats.schedule_steps_ms.size(); ++step) {
    stats.schedule_steps_ms[step] = TimeSummary{0.125 * double(step + 1), 0.0625, 2.0};
  }
  stats.wall_frame_ms = TimeSummary{16.5, 16.25, 33.0};
  stats.lighting = "deferred";
  stats.gpu_frame_ms = TimeSummary{0.5, 0.25, 0.875};
  stats.passes = {{"shadow_atlas", {0.125, 0.0625, 0.25}}, {"lighting", {0.375, 0.25, 0.5}}};
  stats.settled = RunStats::Settled{5,
                                    7,
                                    TimeSummary{1.25, 1.125, 2.5},
                                    TimeSummary{16.25, 16.125, 17.0},
                                    TimeSummary{0.375, 0.25, 0.5},
                                    {{"lighting", {0.25, 0.125, 0.375}}}};
  stats.validation_errors = 4;
  stats.shadow_map_bytes = 67'108'864;
  stats.dropped_light_pairs = 12;
  stats.light_tiles_cut = 3;
  stats.light_list_pairs = TimeSummary{5000.0, 4000.0, 6000.0};
  stats.filtered_shadows = 8;
  stats.contact_shadows_skipped = 3;
  stats.shadows = {"batched",
                   "compute",
                   "nearest",
                   1ull << 30,
                   4096,
                   1,
                   12'345'678,
                   {{64, 200}, {256, 10}},
                   3,
                   2,
                   4,
                   TimeSummary{100.0, 50.0, 3584.0},
                   TimeSummary{20.0, 0.0, 40.0},
                   TimeSummary{60.0, 6.0, 600.0},
                   98'765,
                   TimeSummary{1.0, 0.0, 2.0},
                   TimeSummary{3.0, 1.0, 5.0},
                   TimeSummary{4.0, 2.0, 9.0},
                   TimeSummary{12.0, 0.0, 40.0},
                   TimeSummary{30.0, 1.0, 900.0},
                   3,
                   2,
                   {{"spot east", 512, 1u << 20, 7, "on_demand", 1.5f}}};
  stats.shadow_budget = {6.0,
                         TimeSummary{5.5, 2.25, 19.0},
                         120,
                         7,
                         TimeSummary{40.0, 0.0, 300.0},
                         TimeSummary{0.0, 0.0, 64.0},
                         TimeSummary{0.0, 0.0, 12.0},
                         TimeSummary{0.0, 0.0, 3.0},
                         1.25,
                         96};
  stats.settings = {{"width", SettingType::whole, "640"},
                    {"exposure", SettingType::number, "0.5"},
                    {"naive", SettingType::flag, "true"},
                    {"lighting", SettingType::choice, "deferred"},
                    {"camera", SettingType::text, std::nullopt}};
  stats.pipelines = {{{"tiled lighting", "Compute Shader", {{"Register Count", 64}, {"Spills", 0}}}}};

  TempDir dir;
  const std::string path = dir.path("stats.json").string();
  write_stats_json(path, stats);
  const nlohmann::json json = read_json(path);

  EXPECT_EQ(json.size(), 28u) << json.dump(2);  // no unexpected top-level keys
  EXPECT_EQ(json.at("schema_version"), stats_schema_version);
  EXPECT_EQ(json.at("generator"), "Shadowgraph " SHADOWGRAPH_VERSION);
  EXPECT_EQ(json.at("device"), stats.device);
  EXPECT_EQ(json.at("resolution"), nlohmann::json({{"width", 640}, {"height", 360}}));
  EXPECT_EQ(json.at("scene_resolution"), nlohmann::json({{"width", 320}, {"height", 180}}));
  EXPECT_EQ(json.at("render_scale_changes"), 3);
  EXPECT_EQ(json.at("frames"), 12);
  EXPECT_EQ(json.at("interrupted"), true);
  const nlohmann::json& scene = json.at("scene");
  EXPECT_EQ(scene.size(), 5u) << scene.dump(2);
  EXPECT_EQ(scene.at("name"), "stress");
  EXPECT_EQ(scene.at("triangles"), 250'123);
  EXPECT_EQ(scene.at("entities"), 4'321);
  EXPECT_EQ(scene.at("mesh_instances"), 1'234);
  EXPECT_EQ(scene.at("lights"),
            nlohmann::json(
                {{"point", 32}, {"spot", 31}, {"directional", 1}, {"cylinder", 2}, {"shadow_casting", 60}}));
  expect_summary(json.at("cpu_frame_ms"), *stats.cpu_frame_ms);
  expect_summary(json.at("wall_frame_ms"), *stats.wall_frame_ms);
  const nlohmann::json& phases = json.at("cpu_phases_ms");
  EXPECT_EQ(phases.size(), 10u);
  expect_summary(phases.at("update"), *stats.cpu_phases_ms.update);
  expect_summary(phases.at("prepare"), *stats.cpu_phases_ms.prepare);
  expect_summary(phases.at("execute"), *stats.cpu_phases_ms.execute);
  expect_summary(phases.at("gather_lights"), *stats.cpu_phases_ms.lights);
  expect_summary(phases.at("prepare_upload"), *stats.cpu_phases_ms.upload);
  expect_summary(phases.at("prepare_views"), *stats.cpu_phases_ms.views);
  const nlohmann::json& steps = json.at("schedule_steps_ms");
  ASSERT_EQ(steps.size(), shadows::schedule_step_count);
  expect_summary(steps.at("views"), *stats.schedule_steps_ms[0]);
  expect_summary(steps.at("budget"), *stats.schedule_steps_ms[3]);
  expect_summary(steps.at("apply"), *stats.schedule_steps_ms[10]);
  EXPECT_EQ(json.at("lighting"), "deferred");
  expect_summary(json.at("gpu_frame_ms"), *stats.gpu_frame_ms);
  const nlohmann::json& passes = json.at("passes");
  ASSERT_EQ(passes.size(), 2u);
  for (std::size_t i = 0; i < passes.size(); ++i) {
    EXPECT_EQ(passes[i].size(), 2u) << passes[i].dump();
    EXPECT_EQ(passes[i].at("name"), stats.passes[i].name);
    expect_summary(passes[i].at("gpu_ms"), stats.passes[i].gpu_ms);
  }
  const nlohmann::json& settled = json.at("settled");
  EXPECT_EQ(settled.size(), 6u) << settled.dump(2);
  EXPECT_EQ(settled.at("from_frame"), 5);
  EXPECT_EQ(settled.at("frames"), 7);
  expect_summary(settled.at("cpu_frame_ms"), *stats.settled->cpu_frame_ms);
  expect_summary(settled.at("wall_frame_ms"), *stats.settled->wall_frame_ms);
  expect_summary(settled.at("gpu_frame_ms"), *stats.settled->gpu_frame_ms);
  ASSERT_EQ(settled.at("passes").size(), 1u);
  EXPECT_EQ(settled.at("passes")[0].at("name"), "lighting");
  expect_summary(settled.at("passes")[0].at("gpu_ms"), stats.settled->passes[0].gpu_ms);
  EXPECT_EQ(json.at("validation_errors"), 4);
  EXPECT_EQ(json.at("shadow_map_bytes"), 67'108'864);
  EXPECT_EQ(json.at("dropped_light_pairs"), 12);
  EXPECT_EQ(json.at("light_tiles_cut"), 3);
  EXPECT_EQ(json.at("contact_shadows_skipped"), 3);
  EXPECT_EQ(json.at("filtered_shadows"), 8);
  expect_summary(json.at("light_list_pairs"), *stats.light_list_pairs);
  // Settings keep their types: numbers, true/false for flags, null when unset.
  EXPECT_EQ(json.at("settings"), nlohmann::json({{"width", 640},
                                                 {"exposure", 0.5},
                                                 {"naive", true},
                                                 {"lighting", "deferred"},
                                                 {"camera", nullptr}}));
  const nlohmann::json& shadows = json.at("shadows");
  EXPECT_EQ(shadows.size(), 20u) << shadows.dump(2);
  EXPECT_EQ(shadows.at("views"), "batched");
  EXPECT_EQ(shadows.at("raster"), "compute");
  EXPECT_EQ(shadows.at("comparison_filter"), "nearest");
  EXPECT_EQ(shadows.at("budget_bytes"), 1ull << 30);
  EXPECT_EQ(shadows.at("page_size"), 4096);
  EXPECT_EQ(shadows.at("pages"), 1);
  EXPECT_EQ(shadows.at("used_bytes"), 12'345'678);
  EXPECT_EQ(shadows.at("lights_per_resolution"), nlohmann::json({{"64", 200}, {"256", 10}}));
  EXPECT_EQ(shadows.at("lights_without_shadow"), 3);
  EXPECT_EQ(shadows.at("lights_waiting"), 2);
  EXPECT_EQ(shadows.at("cascades"), 4);
  expect_summary(shadows.at("views_rendered"), *stats.shadows.views_rendered);
  expect_summary(shadows.at("views_cached"), *stats.shadows.views_cached);
  expect_summary(shadows.at("views_moving_only"), *stats.shadows.views_moving_only);
  EXPECT_EQ(shadows.at("caster_draws"), 98'765);
  expect_summary(shadows.at("map_lag_frames").at("p50"), *stats.shadows.map_lag_p50);
  expect_summary(shadows.at("map_lag_frames").at("p99"), *stats.shadows.map_lag_p99);
  expect_summary(shadows.at("map_lag_frames").at("max"), *stats.shadows.map_lag_max);
  expect_summary(shadows.at("lights_changed_tier"), *stats.shadows.lights_changed_tier);
  expect_summary(shadows.at("lights_retiled"), *stats.shadows.lights_retiled);
  EXPECT_EQ(shadows.at("atlas_repacks"), 3);
  EXPECT_EQ(shadows.at("maps"), nlohmann::json({{"total", 2},
                                                {"largest",
                                                 {{{"name", "spot east"},
                                                   {"resolution", 512},
                                                   {"bytes", 1 << 20},
                                                   {"frames_since_drawn", 7},
                                                   {"update", "on_demand"},
                                                   {"priority", 1.5}}}}}));
  const nlohmann::json& budget = json.at("shadow_budget");
  EXPECT_EQ(budget.size(), 10u) << budget.dump(2);
  EXPECT_EQ(budget.at("budget_ms"), 6.0);
  expect_summary(budget.at("measured_ms"), *stats.shadow_budget.measured_ms);
  EXPECT_EQ(budget.at("bound"), "time") << "more frames held down by time than by memory";
  EXPECT_EQ(budget.at("frames_bound"), nlohmann::json({{"time", 120}, {"memory", 7}}));
  expect_summary(budget.at("lights_demoted_by_time"), *stats.shadow_budget.lights_demoted_by_time);
  expect_summary(budget.at("views_deferred_by_time"), *stats.shadow_budget.views_deferred_by_time);
  expect_summary(budget.at("lights_demoted_by_memory"), *stats.shadow_budget.lights_demoted_by_memory);
  expect_summary(budget.at("lights_dropped_by_memory"), *stats.shadow_budget.lights_dropped_by_memory);
  EXPECT_EQ(budget.at("lowered_tiers"), 1.25);
  EXPECT_EQ(budget.at("view_cap"), 96);
  EXPECT_EQ(json.at("pipelines"), nlohmann::json::parse(R"([{"pipeline": "tiled lighting",
      "executable": "Compute Shader", "statistics": {"Register Count": 64, "Spills": 0}}])"));
}

TEST(StatsJson, TheShadowBudgetBoundIsTheOneThatHeldTheMostFramesDown) {
  RunStats stats;
  stats.shadow_budget.frames_bound_by_memory = 3;
  stats.shadow_budget.frames_bound_by_time = 2;
  TempDir dir;
  const std::string path = dir.path("stats.json").string();
  write_stats_json(path, stats);
  EXPECT_EQ(read_json(path).at("shadow_budget").at("bound"), "memory");
  stats.shadow_budget.frames_bound_by_time = 3;
  write_stats_json(path, stats);
  EXPECT_EQ(read_json(path).at("shadow_budget").at("bound"), "time");
}

TEST(StatsJson, MissingMeasurementsAreNull) {
  RunStats stats;  // no frames, no timestamps, validation off, no passes
  TempDir dir;
  const std::string path = dir.path("empty.json").string();
  write_stats_json(path, stats);
  const nlohmann::json json = read_json(path);
  EXPECT_TRUE(json.at("cpu_frame_ms").is_null());
  EXPECT_TRUE(json.at("wall_frame_ms").is_null());
  EXPECT_TRUE(json.at("gpu_frame_ms").is_null());
  EXPECT_TRUE(json.at("settled").is_null()) << "no frame in which every light had its map";
  EXPECT_TRUE(json.at("validation_errors").is_null());
  EXPECT_TRUE(json.at("pipelines").is_null()) << "no statistics kept";
  EXPECT_TRUE(json.at("passes").is_array());
  EXPECT_TRUE(json.at("passes").empty());
  EXPECT_EQ(json.at("frames"), 0);
  EXPECT_TRUE(json.at("shadows").at("views_rendered").is_null());
  EXPECT_TRUE(json.at("light_list_pairs").is_null());
  const nlohmann::json& budget = json.at("shadow_budget");
  EXPECT_TRUE(budget.at("budget_ms").is_null()) << "no time budget";
  EXPECT_TRUE(budget.at("measured_ms").is_null());
  EXPECT_EQ(budget.at("bound"), "none");
  EXPECT_TRUE(budget.at("view_cap").is_null());
}

TEST(StatsJson, ReplacesAnExistingFile) {
  TempDir dir;
  const std::string path = dir.path("stats.json").string();
  scene::test::write_file(path, std::string(4096, 'x'));  // longer than the JSON
  RunStats stats;
  stats.frames = 3;
  write_stats_json(path, stats);
  EXPECT_EQ(read_json(path).at("frames"), 3);
}

TEST(StatsJson, UnwritablePathNamesThePathAndTheReason) {
  TempDir dir;
  const std::string path = dir.path("no-such-dir").string() + "/stats.json";
  try {
    write_stats_json(path, RunStats{});
    ADD_FAILURE() << "wrote into a missing directory";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace sg::sandbox
