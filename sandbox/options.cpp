#include "sandbox/options.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "rendergraph/device/context.h"
#include "systems/scene/scene_error.h"

namespace sg::sandbox {
namespace {

// CLI11 reads unsigned integers with strtoull in base 0, so "-3" wraps around to 2^64 - 3 and
// "010" is octal. Checking the text first gives plain decimal numbers and a message that says
// what is allowed; the text is rewritten in canonical form so CLI11's conversion agrees.
CLI::Validator whole_number(std::uint64_t min, std::uint64_t max) {
  const std::string allowed = "a whole number in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  return CLI::Validator(
      [min, max, allowed](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || error != std::errc{} || stop != end || value < min || value > max) {
          return "\"" + text + "\" is not " + allowed;
        }
        text = std::to_string(value);
        return {};
      },
      // The same --help wording as CLI::Range ("UINT:UINT in [1 - 16384]").
      "UINT in [" + std::to_string(min) + " - " + std::to_string(max) + "]");
}

// CLI::Range lets "nan" through (every comparison with NaN is false).
CLI::Validator fraction() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        float value = 0.0f;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || error != std::errc{} || stop != end || !std::isfinite(value) || value < 0.0f ||
            value > 1.0f) {
          return "\"" + text + "\" is not a number in [0, 1]";
        }
        return {};
      },
      "FLOAT in [0 - 1]");
}

// An option whose value is one of `choices`' names, setting `target` to that name's value. Its
// default, shown by --help, is the name of the value `target` holds when the option is added.
template <class T>
CLI::Option* add_choice(CLI::App& app, const std::string& name, T& target,
                        std::vector<std::pair<std::string, T>> choices, const std::string& help) {
  std::vector<std::string> names;
  std::string default_name;
  for (const auto& [choice, value] : choices) {
    names.push_back(choice);
    if (value == target) default_name = choice;
  }
  return app
      .add_option_function<std::string>(
          name,
          [&target, choices = std::move(choices)](const std::string& text) {
            for (const auto& [choice, value] : choices) {
              if (choice == text) target = value;
            }
          },
          help)
      ->check(CLI::IsMember(names))
      ->default_str(default_name);
}

}  // namespace

void add_options(CLI::App& app, Options& o) {
  app.add_flag("--headless", o.headless, "Render offscreen even when a display is available");
  app.add_option("--width", o.width, "Output width in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option("--height", o.height, "Output height in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option("--frames", o.frames, "Frames to render, then exit")->check(CLI::Range(1u, 1000000u));
  app.add_option("--screenshot", o.screenshot, "Write the last frame to this PNG file");
  app.add_option("--device", o.device, "Use the Vulkan device whose name contains this text");
  app.add_flag("--validation", o.validation,
               "Enable the Khronos validation layer (also SHADOWGRAPH_VALIDATION=1)");
  app.add_flag("!--no-vsync", o.vsync, "Present without waiting for vertical blank");
  app.add_flag("--depth-overlay", o.depth_overlay,
               "Show the depth buffer in the bottom-right quarter (the render graph's extension example)");
  app.add_flag("--light-heatmap", o.light_heatmap,
               "Color each 16x16 screen tile by the lights it shades (tiled lighting's lists; white: a full "
               "list)");

  app.add_option("--scene", o.scene, "Scene: default, stress, or a .gltf/.glb file")->capture_default_str();
  app.add_option_function<std::string>(
         "--camera",
         [&o](const std::string& text) {
           try {
             o.camera = scene::parse_camera(text);
           } catch (const scene::SceneError& error) {
             // SceneError's message already names --camera and the text.
             throw CLI::ValidationError(error.what());
           }
         },
         "Camera eye and target, overriding the scene's camera")
      ->type_name("EX,EY,EZ,TX,TY,TZ");
  scene::BuiltinSceneParams& params = o.scene_params;
  app.add_option("--scene-triangles", params.triangles, "Stress scene: triangles to reach")
      ->transform(whole_number(1, max_scene_triangles))
      ->capture_default_str();
  app.add_option("--point-lights", params.point_lights, "Stress scene: point lights")
      ->transform(whole_number(0, max_lights_per_type))
      ->capture_default_str();
  app.add_option("--spot-lights", params.spot_lights, "Stress scene: spot lights")
      ->transform(whole_number(0, max_lights_per_type))
      ->capture_default_str();
  app.add_option("--moving-lights", params.moving_fraction,
                 "Stress scene: fraction of lights and crates that move each frame")
      ->check(fraction())
      ->capture_default_str();
  app.add_option("--seed", params.seed, "Stress scene: random seed (equal seeds, equal scenes)")
      ->transform(whole_number(0, std::numeric_limits<std::uint64_t>::max()))
      ->capture_default_str();
  app.add_option("--stats", o.stats_path, "Write facts about the run to this JSON file");

  std::vector<std::string> algorithm_names;
  for (const scene::ShadowAlgorithm a : scene::all_shadow_algorithms) {
    algorithm_names.emplace_back(scene::to_string(a));
  }
  app.add_option_function<std::string>(
         "--algorithm", [&o](const std::string& name) { o.algorithm = scene::parse_shadow_algorithm(name); },
         "Shadow algorithm every light starts with, instead of the scene's (the panel and scripts may change "
         "it)")
      ->check(CLI::IsMember(algorithm_names));
  add_choice(app, "--shadows", o.shadows, {{"on", true}, {"off", false}},
             "on: every light casts its shadow; off: none does");
  add_choice(app, "--cube-shadows", o.cube_shadows,
             {{"layered", shadows::CubeShadowMode::layered}, {"six", shadows::CubeShadowMode::six_passes}},
             "Per-light shadow passes' point-light cubes: layered (one pass, all six faces) or six (one "
             "pass per face)");
  add_choice(
      app, "--shadow-views", o.shadow_views,
      {{"batched", shadows::ShadowViewPath::batched}, {"per-light", shadows::ShadowViewPath::per_light}},
      "batched: every shadow view due in a frame culled on the GPU and drawn by a few passes; "
      "per-light: one pass per view, casters culled on the CPU (the baseline)");
  add_choice(app, "--shadow-raster", o.shadow_raster,
             {{"auto", shadows::ShadowRaster::automatic},
              {"hardware", shadows::ShadowRaster::hardware},
              {"compute", shadows::ShadowRaster::compute}},
             "How batched shadow views are rasterized: hardware (multi-draw indirect), compute, or auto "
             "(on GPUs each frame: compute for many small views, hardware for a few with large tiles; "
             "hardware on CPU devices)");
  add_choice(
      app, "--shadow-resolution", o.shadow_resolution,
      {{"screen", shadows::ShadowResolution::screen}, {"requested", shadows::ShadowResolution::requested}},
      "screen: each light's map as many texels as its reach spans on screen, at most its own "
      "resolution; requested: its own resolution wherever it is seen");
  app.add_option(
         "--shadow-memory", o.shadow_memory_mib,
         "Shadow atlas budget in MiB (0: an eighth of the GPU's memory, 64 to 2048); lights beyond it "
         "lose resolution, then their shadow, least important first")
      ->check(CLI::Range(0u, 1u << 20))
      ->capture_default_str();
  app.add_option("--shadow-updates", o.shadow_updates,
                 "Shadow views (2D maps, cube faces) redrawn per frame at most, stalest first (0: every "
                 "view due)")
      ->check(CLI::Range(0u, 1u << 24))
      ->capture_default_str();
  app.add_option("--threads", o.threads,
                 "Threads for a frame's CPU work split in pieces (gathering, shadow scheduling), the "
                 "frame's own included (0: one per hardware thread)")
      ->check(CLI::Range(0u, 1024u))
      ->capture_default_str();
  add_choice(app, "--shadow-cache", o.shadow_cache, {{"on", true}, {"off", false}},
             "on: a shadow map is redrawn only when its light, or a caster in its reach, moved; off: every "
             "map every frame");
  add_choice(
      app, "--shadow-layers", o.shadow_layers, {{"on", true}, {"off", false}},
      "on: where shadows rasterize in compute, each map keeps a layer of its still casters (twice "
      "the memory a texel) and moving casters are redrawn alone over it; off: every redraw draws every "
      "caster");
  add_choice(app, "--lighting", o.lighting,
             {{"auto", LightingPath::automatic},
              {"deferred", LightingPath::deferred},
              {"fused", LightingPath::fused}},
             "deferred: a G-buffer, light lists per 16x16 screen tile, a compute pass per light group; "
             "fused: a depth prepass and one forward pass of every light that tone-maps too (a few "
             "lights on CPU devices); auto: the fastest for this kind of device");
  add_choice(
      app, "--lit-sum-start", o.lit_sum_start,
      {{"auto", LitSumStart::automatic}, {"pass", LitSumStart::pass}, {"gbuffer", LitSumStart::gbuffer}},
      "Where deferred lighting starts the lit sum (ambient light and background): a full-screen "
      "pass of its own, or a G-buffer target; auto: the G-buffer on CPU devices, the pass on GPUs");
  CLI::Option* naive = app.add_flag(
      "--naive", o.naive,
      "The source documents' way, as a baseline: a pass per shadow view and six per cube, every map "
      "every frame, every caster in every shadow view, every light at every pixel");
  naive->excludes("--lighting")
      ->excludes("--lit-sum-start")
      ->excludes("--cube-shadows")
      ->excludes("--shadow-views")
      ->excludes("--shadow-cache");
  add_choice(app, "--view", o.view, {{"lit", LightingView::lit}, {"shadows", LightingView::shadows}},
             "lit: the picture; shadows: a debug view of white diffuse surfaces under white lights, "
             "shadows at full density, no ambient");
  app.add_option("--exposure", o.exposure, "Multiplies the lit color before tone mapping")
      ->check(CLI::Range(1e-3f, 1e3f))
      ->capture_default_str();
  add_choice(app, "--animate", o.animate, {{"on", true}, {"off", false}},
             "on: play the scene's glTF animations and the stress scene's orbits (headless: a fixed 1/60 s a "
             "frame); off: everything stays where the scene puts it");
  o.sidecar = true;  // the command line's default
  add_choice(
      app, "--sidecar", o.sidecar, {{"on", true}, {"off", false}},
      "on: start from the lights and camera saved beside the scene (SCENE.shadowgraph.json, written by "
      "the panels' save button or a script's save); off: the scene as it is");
  app.add_option(
         "--script", o.script,
         "Run FILE's commands headless (select NAME, algorithm NAME, resolution N, move X Y Z, camera "
         "EX,EY,EZ,TX,TY,TZ, view lit|shadows, wait N, screenshot PATH, save) instead of --frames")
      ->excludes("--frames");
  app.add_option_function<std::string>(
         "--ui", [&o](const std::string& value) { o.ui = value == "on"; },
         "on: the frame-facts and light-editor panels (Dear ImGui) over the picture; off: the picture "
         "alone (default: on in a window, off headless)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--dump-shadow-maps", o.dump_shadow_maps,
                 "After the run, write each light's shadow map as PNG into this folder");
}

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, Options& options) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 has an exit code per kind of error; the sandbox promises 2 for every usage error.
    const bool usage_error = app.exit(e) != static_cast<int>(CLI::ExitCodes::Success);
    return usage_error ? 2 : 0;
  }
  options.validation = options.validation || vk::validation_requested_by_environment();
  return std::nullopt;
}

ParseResult parse_options(int argc, char** argv) {
  Options o;
  CLI::App app{"Shadowgraph sandbox: renders a scene in a window, or headless to a PNG."};
  add_options(app, o);
  if (const std::optional<int> exit_code = parse_command_line(app, argc, argv, o)) {
    return {std::nullopt, *exit_code};
  }
  return {o, 0};
}

vk::ContextOptions context_options(const Options& options) {
  vk::ContextOptions context;
  context.validation = options.validation;
  context.device_name = options.device;
  return context;
}

}  // namespace sg::sandbox
