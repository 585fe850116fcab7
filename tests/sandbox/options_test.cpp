// SPDX-License-Identifier: MIT
// The sandbox's command line: defaults, each option, and each refusal (exit code 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sandbox/options.h"

namespace sg::sandbox {
namespace {

ParseResult parse(std::vector<std::string> args) {
  args.insert(args.begin(), "shadowgraph-sandbox");
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  return parse_options(static_cast<int>(argv.size()), argv.data());
}

Options parse_ok(const std::vector<std::string>& args) {
  const ParseResult result = parse(args);
  EXPECT_EQ(result.exit_code, 0);
  if (!result.options) throw std::runtime_error("refused a valid command line");
  return *result.options;
}

TEST(SandboxOptions, DefaultsComeFromTheSceneLibrary) {
  const Options options = parse_ok({});
  const scene::BuiltinSceneParams defaults;
  EXPECT_EQ(options.frame.scene, "default");
  EXPECT_FALSE(options.frame.camera.has_value());
  EXPECT_EQ(options.frame.scene_params.triangles, defaults.triangles);
  EXPECT_EQ(options.frame.scene_params.point_lights, defaults.point_lights);
  EXPECT_EQ(options.frame.scene_params.spot_lights, defaults.spot_lights);
  EXPECT_EQ(options.frame.scene_params.moving_fraction, defaults.moving_fraction);
  EXPECT_EQ(options.frame.scene_params.seed, defaults.seed);
  EXPECT_TRUE(options.stats_path.empty());
  EXPECT_EQ(options.frame.width, 1280u);
  EXPECT_EQ(options.frame.height, 720u);
  EXPECT_FALSE(options.frames.has_value());
  EXPECT_TRUE(options.vsync);
}

TEST(SandboxOptions, ExistingOptionsStillWork) {
  const Options options =
      parse_ok({"--headless", "--width", "320", "--height", "200", "--frames", "5", "--screenshot", "a.png",
                "--device", "llvmpipe", "--validation", "--no-vsync"});
  EXPECT_TRUE(options.headless);
  EXPECT_EQ(options.frame.width, 320u);
  EXPECT_EQ(options.frame.height, 200u);
  EXPECT_EQ(options.frames, 5u);
  EXPECT_EQ(options.screenshot, "a.png");
  EXPECT_EQ(options.frame.device, "llvmpipe");
  EXPECT_TRUE(options.frame.validation);
  EXPECT_FALSE(options.vsync);
}

TEST(SandboxOptions, RenderScaleIsAFractionOfTheOutput) {
  EXPECT_FALSE(parse_ok({}).frame.render_scale.has_value()) << "unset: the device decides";
  EXPECT_EQ(parse_ok({"--render-scale", "0.5"}).frame.render_scale, 0.5f);
  EXPECT_EQ(parse_ok({"--render-scale", "1"}).frame.render_scale, 1.0f);
  for (const char* bad : {"0", "0.1", "1.5", "half"}) {
    EXPECT_EQ(parse({"--render-scale", bad}).exit_code, 2) << bad;
  }
}

TEST(SandboxOptions, ShadowOptions) {
  const Options defaults = parse_ok({});
  EXPECT_FALSE(defaults.frame.algorithm.has_value());
  EXPECT_TRUE(defaults.frame.renderer.lights.shadows);
  EXPECT_EQ(defaults.frame.renderer.cube_shadows, shadows::CubeShadowMode::layered);
  EXPECT_FALSE(defaults.depth_overlay);
  EXPECT_TRUE(defaults.dump_shadow_maps.empty());

  const Options options = parse_ok({"--algorithm", "pcss_noise", "--shadows", "off", "--cube-shadows", "six",
                                    "--depth-overlay", "--dump-shadow-maps", "maps"});
  EXPECT_EQ(options.frame.algorithm, scene::ShadowAlgorithm::pcss_noise);
  EXPECT_FALSE(options.frame.renderer.lights.shadows);
  EXPECT_EQ(options.frame.renderer.cube_shadows, shadows::CubeShadowMode::six_passes);
  EXPECT_TRUE(options.depth_overlay);
  EXPECT_EQ(options.dump_shadow_maps, "maps");

  for (const std::vector<std::string>& bad : {std::vector<std::string>{"--algorithm", "soft"},
                                              {"--shadows", "maybe"},
                                              {"--cube-shadows", "five"}}) {
    EXPECT_EQ(parse(bad).exit_code, 2) << bad[0];
  }
}

TEST(SandboxOptions, ShadowStorageAndAnimationOptions) {
  const Options defaults = parse_ok({});
  EXPECT_EQ(defaults.frame.renderer.shadow_views, shadows::ShadowViewPath::batched);
  EXPECT_EQ(defaults.frame.renderer.shadow_raster, shadows::ShadowRaster::automatic);
  EXPECT_EQ(defaults.frame.renderer.shadow_memory_mib, 0u);
  EXPECT_EQ(defaults.frame.renderer.shadow_view_budget, shadows::default_shadow_view_budget);
  EXPECT_EQ(defaults.frame.renderer.cpu_threads, 0u);
  EXPECT_TRUE(defaults.frame.renderer.cache_shadows);
  EXPECT_TRUE(defaults.frame.renderer.static_shadow_layers);
  EXPECT_TRUE(defaults.frame.animate);
  EXPECT_TRUE(defaults.frame.sidecar);  // from the command line; Options{} has it off
  EXPECT_FALSE(Options{}.frame.sidecar);

  const Options options =
      parse_ok({"--shadow-views", "per-light", "--shadow-raster", "compute", "--shadow-memory", "128",
                "--shadow-updates", "0", "--shadow-cache", "off", "--shadow-layers", "off", "--animate",
                "off", "--sidecar", "off", "--threads", "4"});
  EXPECT_EQ(options.frame.renderer.shadow_views, shadows::ShadowViewPath::per_light);
  EXPECT_EQ(options.frame.renderer.shadow_raster, shadows::ShadowRaster::compute);
  EXPECT_EQ(options.frame.renderer.shadow_memory_mib, 128u);
  EXPECT_EQ(options.frame.renderer.shadow_view_budget, 0u);
  EXPECT_FALSE(options.frame.renderer.cache_shadows);
  EXPECT_FALSE(options.frame.renderer.static_shadow_layers);
  EXPECT_FALSE(options.frame.animate);
  EXPECT_FALSE(options.frame.sidecar);
  EXPECT_EQ(options.frame.renderer.cpu_threads, 4u);

  for (const std::vector<std::string>& bad : {std::vector<std::string>{"--shadow-views", "some"},
                                              {"--threads", "-2"},
                                              {"--shadow-raster", "gpu"},
                                              {"--shadow-memory", "-1"},
                                              {"--shadow-cache", "maybe"},
                                              {"--shadow-layers", "some"},
                                              {"--animate", "yes"},
                                              {"--naive", "--shadow-views", "batched"},
                                              {"--naive", "--lit-sum-start", "pass"}}) {
    EXPECT_EQ(parse(bad).exit_code, 2) << bad[0] << " " << bad[1];
  }
}

TEST(SandboxOptions, LightingOptions) {
  const Options defaults = parse_ok({});
  EXPECT_EQ(defaults.frame.renderer.lighting, LightingPath::automatic);
  EXPECT_EQ(defaults.frame.renderer.exposure, 1.0f);
  EXPECT_FALSE(defaults.frame.naive);
  EXPECT_EQ(parse_ok({"--lighting", "fused"}).frame.renderer.lighting, LightingPath::fused);
  EXPECT_EQ(defaults.frame.renderer.lit_sum_start, LitSumStart::automatic);
  EXPECT_EQ(parse_ok({"--lit-sum-start", "pass"}).frame.renderer.lit_sum_start, LitSumStart::pass);
  EXPECT_EQ(parse_ok({"--lit-sum-start", "gbuffer"}).frame.renderer.lit_sum_start, LitSumStart::gbuffer);
  EXPECT_EQ(defaults.frame.renderer.light_records, LightRecordsIn::automatic);
  EXPECT_EQ(parse_ok({"--light-records", "storage"}).frame.renderer.light_records,
            LightRecordsIn::storage_buffer);
  EXPECT_EQ(parse_ok({"--light-records", "texel"}).frame.renderer.light_records,
            LightRecordsIn::texel_buffer);
  EXPECT_EQ(parse_ok({"--lighting", "deferred", "--exposure", "0.5"}).frame.renderer.exposure, 0.5f);
  EXPECT_TRUE(parse_ok({"--naive"}).frame.naive);
  for (const std::vector<std::string>& bad : {std::vector<std::string>{"--lighting", "raytraced"},
                                              {"--exposure", "0"},
                                              {"--naive", "--lighting", "deferred"},
                                              {"--deferred-passes", "compute"},
                                              {"--naive", "--lit-sum-start", "pass"},
                                              {"--light-records", "uniform"},
                                              {"--naive", "--light-records", "storage"},
                                              {"--naive", "--cube-shadows", "layered"}}) {
    EXPECT_EQ(parse(bad).exit_code, 2) << bad[0] << " " << bad[1];
  }
}

TEST(SandboxOptions, SceneOptions) {
  const Options options =
      parse_ok({"--scene", "stress", "--scene-triangles", "5000", "--point-lights", "4", "--spot-lights", "0",
                "--moving-lights", "0.5", "--seed", "42", "--stats", "out.json"});
  EXPECT_EQ(options.frame.scene, "stress");
  EXPECT_EQ(options.frame.scene_params.triangles, 5000u);
  EXPECT_EQ(options.frame.scene_params.point_lights, 4u);
  EXPECT_EQ(options.frame.scene_params.spot_lights, 0u);
  EXPECT_EQ(options.frame.scene_params.moving_fraction, 0.5f);
  EXPECT_EQ(options.frame.scene_params.seed, 42u);
  EXPECT_EQ(options.stats_path, "out.json");
  EXPECT_EQ(parse_ok({"--scene", "models/room.gltf"}).frame.scene, "models/room.gltf");
}

TEST(SandboxOptions, BoundaryValuesAreAccepted) {
  const Options options = parse_ok({"--scene-triangles", std::to_string(max_scene_triangles),
                                    "--point-lights", std::to_string(max_lights_per_type), "--moving-lights",
                                    "1", "--seed", "18446744073709551615"});
  EXPECT_EQ(options.frame.scene_params.triangles, max_scene_triangles);
  EXPECT_EQ(options.frame.scene_params.point_lights, max_lights_per_type);
  EXPECT_EQ(options.frame.scene_params.moving_fraction, 1.0f);
  EXPECT_EQ(options.frame.scene_params.seed, 18446744073709551615u);
  EXPECT_EQ(parse_ok({"--moving-lights", "0"}).frame.scene_params.moving_fraction, 0.0f);
}

TEST(SandboxOptions, NumbersAreDecimal) {
  // CLI11 alone would read a leading zero as octal (010 -> 8).
  EXPECT_EQ(parse_ok({"--seed", "010"}).frame.scene_params.seed, 10u);
  EXPECT_EQ(parse_ok({"--point-lights", "07"}).frame.scene_params.point_lights, 7u);
}

TEST(SandboxOptions, AmbientIsParsedPerChannel) {
  EXPECT_EQ(parse_ok({}).frame.renderer.ambient, glm::vec3(0.15f));
  EXPECT_EQ(parse_ok({"--ambient", "0.3,0.1,0"}).frame.renderer.ambient, glm::vec3(0.3f, 0.1f, 0.0f));
}

TEST(SandboxOptions, CameraIsParsed) {
  const Options options = parse_ok({"--camera", "1,2.5,-3,0,0,10"});
  ASSERT_TRUE(options.frame.camera.has_value());
  EXPECT_EQ(options.frame.camera->eye, glm::vec3(1, 2.5f, -3));
  EXPECT_EQ(options.frame.camera->target, glm::vec3(0, 0, 10));
  // A leading minus sign is not taken for an option.
  const Options negative = parse_ok({"--camera", "-4,1,0,0,0,0"});
  ASSERT_TRUE(negative.frame.camera.has_value());
  EXPECT_EQ(negative.frame.camera->eye, glm::vec3(-4, 1, 0));
}

struct Refusal {
  std::vector<std::string> args;
  std::string message;  // a fragment of what the user is told
};

// Each command line is refused with exit code 2 and its message.
void expect_refused(const std::vector<Refusal>& refusals) {
  for (const Refusal& refusal : refusals) {
    testing::internal::CaptureStderr();
    const ParseResult result = parse(refusal.args);
    const std::string printed = testing::internal::GetCapturedStderr();
    const std::string command_line = refusal.args[0] + (refusal.args.size() > 1 ? " " + refusal.args[1] : "");
    EXPECT_FALSE(result.options.has_value()) << command_line;
    EXPECT_EQ(result.exit_code, 2) << command_line;
    EXPECT_NE(printed.find(refusal.message), std::string::npos) << command_line << " printed: " << printed;
  }
}

TEST(SandboxOptions, ImpossibleValuesAreUsageErrors) {
  const std::vector<Refusal> refusals = {
      {{"--scene-triangles", "0"}, "\"0\" is not a whole number in [1, 100000000]"},
      {{"--scene-triangles", "-5"}, "\"-5\" is not a whole number in [1, 100000000]"},
      {{"--scene-triangles", "100000001"}, "is not a whole number in [1, 100000000]"},
      {{"--point-lights", "-1"}, "\"-1\" is not a whole number in [0, 100000]"},
      {{"--point-lights", "many"}, "\"many\" is not a whole number"},
      {{"--spot-lights", "1.5"}, "\"1.5\" is not a whole number in [0, 100000]"},
      {{"--spot-lights", "100001"}, "\"100001\" is not a whole number in [0, 100000]"},
      {{"--moving-lights", "1.5"}, "\"1.5\" is not a number in [0, 1]"},
      {{"--moving-lights", "-0.1"}, "\"-0.1\" is not a number in [0, 1]"},
      {{"--moving-lights", "nan"}, "\"nan\" is not a number in [0, 1]"},
      {{"--seed", "-1"}, "\"-1\" is not a whole number"},
      {{"--seed", "18446744073709551616"}, "is not a whole number"},
      {{"--camera", "1,2,3"}, "--camera \"1,2,3\": value list: expected 6 numbers"},
      {{"--camera", "1,2,x,4,5,6"}, "value 3: \"x\" is not a finite number"},
      {{"--camera", "1,2,3,1,2,3"}, "eye and target are the same point"},
      {{"--ambient", "0.1,0.1"}, "takes three numbers from 0 to 16, R,G,B, got \"0.1,0.1\""},
      {{"--ambient", "1,1,-1"}, "got \"1,1,-1\""},
      {{"--ambient", "1,1,1,"}, "got \"1,1,1,\""},
      {{"--width", "0"}, "--width"},
      {{"--no-such-option"}, "--no-such-option"},
      {{"--scene"}, "--scene"},
  };
  expect_refused(refusals);
}

// The files a run writes at its end are checked before its first frame: a mistyped folder costs
// nothing, where it once cost the run and, for the screenshot, its --stats too.
TEST(SandboxOptions, OutputsThatCannotBeWrittenAreUsageErrors) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "shadowgraph-options-test";
  std::filesystem::create_directories(folder);
  const std::filesystem::path missing = folder / "missing";
  expect_refused({
      {{"--stats", (missing / "run.json").string()},
       std::string("the folder \"").append(missing.string()).append("\" does not exist")},
      {{"--screenshot", folder.string()},
       std::string(1, '"').append(folder.string()).append("\" is a folder, not a file")},
      {{"--export-gltf", (missing / "scene.glb").string()}, "does not exist"},
  });
  const std::string stats = (folder / "run.json").string();
  EXPECT_EQ(parse_ok({"--stats", stats}).stats_path, stats);
  EXPECT_TRUE(parse_ok({"--screenshot", ""}).screenshot.empty());  // empty: no file
}

TEST(SandboxOptions, HelpExitsWithZero) {
  testing::internal::CaptureStdout();
  const ParseResult result = parse({"--help"});
  const std::string printed = testing::internal::GetCapturedStdout();
  EXPECT_FALSE(result.options.has_value());
  EXPECT_EQ(result.exit_code, 0);
  for (const char* option : {"--scene", "--camera", "--scene-triangles", "--point-lights", "--spot-lights",
                             "--moving-lights", "--seed", "--stats"}) {
    EXPECT_NE(printed.find(option), std::string::npos) << option;
  }
}

// The README's option list is the table's (options_table), option for option: a setting added,
// renamed or reworded in the table and not in the README fails here, with the list to paste.
// --camera takes a pose (numbers, with commas) or a camera's name (checked when the scene loads).
TEST(SandboxOptions, CameraTakesAPoseOrAName) {
  const Options named = parse_ok({"--camera", "street"});
  EXPECT_EQ(named.frame.camera_name, "street");
  EXPECT_FALSE(named.frame.camera.has_value());
  const Options posed = parse_ok({"--camera", "1,2,3,4,5,6"});
  EXPECT_TRUE(posed.frame.camera.has_value());
  EXPECT_TRUE(posed.frame.camera_name.empty());
  EXPECT_EQ(parse({"--camera", "1,2,3"}).exit_code, 2);
}

TEST(SandboxOptions, TheReadmeListsEveryOptionAsTheTableDeclaresIt) {
  std::ifstream file(std::string(SHADOWGRAPH_SOURCE_DIR) + "/README.md");
  std::stringstream readme;
  readme << file.rdbuf();
  const std::string text = readme.str();
  const std::string opening = "build/sandbox/shadowgraph-sandbox [options]\n";
  const size_t start = text.find(opening);
  ASSERT_NE(start, std::string::npos) << "the README has no option list";
  const size_t first = start + opening.size();
  const std::string listed = text.substr(first, text.find("```", first) - first);
  const std::string expected = option_list();
  if (listed != expected) {
    std::ofstream("readme_options.txt") << expected;
    FAIL() << "README.md's option list differs from the settings tables; the list they declare is in "
              "readme_options.txt (the test's working folder):\n"
           << expected;
  }
}

// Every setting has a help text, a unique name, and a value that --stats can echo.
TEST(SandboxOptions, EverySettingIsDeclaredOnce) {
  std::vector<std::string_view> names;
  const Options defaults = parse_ok({});
  for (const Setting<Options>& setting : options_table()) {
    EXPECT_FALSE(setting.info.help.empty()) << setting.info.name;
    EXPECT_EQ(std::count(names.begin(), names.end(), setting.info.name), 0) << setting.info.name;
    names.push_back(setting.info.name);
    if (setting.info.type == SettingType::choice && setting.get(defaults)) {
      const std::string value = *setting.get(defaults);
      EXPECT_NE(std::find(setting.info.choices.begin(), setting.info.choices.end(), value),
                setting.info.choices.end())
          << setting.info.name << "'s default is not one of its choices";
    }
  }
}

}  // namespace
}  // namespace sg::sandbox
