#pragma once
// Command line of shadowgraph-sandbox.
#include <cstdint>
#include <optional>
#include <string>

#include "rendergraph/device/fwd.h"
#include "systems/lighting/lighting_path.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/camera.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/cube_shadow_mode.h"
#include "systems/shadows/shadow_resolution.h"
#include "systems/shadows/shadow_view_path.h"

namespace CLI {
class App;
}

namespace sg::sandbox {

struct Options {
  bool headless = false;
  uint32_t width = 1280;
  uint32_t height = 720;
  std::optional<uint32_t> frames;  // unset: headless renders 3, a window runs until closed
  std::string screenshot;          // PNG of the last frame; headless defaults to shadowgraph.png
  std::string device;              // substring of the Vulkan device name
  bool validation = false;         // also on with SHADOWGRAPH_VALIDATION=1
  bool vsync = true;
  std::string scene = "default";                    // a built-in scene name or a .gltf/.glb path
  std::optional<scene::CameraPose> camera;          // --camera; unset: the scene's camera or framing
  scene::BuiltinSceneParams scene_params;           // the stress scene's size, lights and seed
  std::string stats_path;                           // --stats: JSON facts about the run; empty: none
  bool depth_overlay = false;                       // --depth-overlay: the render-graph extension example
  bool light_heatmap = false;                       // --light-heatmap: lights per screen tile
  std::optional<scene::ShadowAlgorithm> algorithm;  // --algorithm: every light starts with this one
  bool shadows = true;                              // --shadows off: no light casts a shadow
  shadows::CubeShadowMode cube_shadows = shadows::CubeShadowMode::layered;  // --cube-shadows layered|six
  shadows::ShadowViewPath shadow_views = shadows::ShadowViewPath::batched;  // --shadow-views
  shadows::ShadowRaster shadow_raster = shadows::ShadowRaster::automatic;   // --shadow-raster
  shadows::ShadowResolution shadow_resolution = shadows::ShadowResolution::screen;  // --shadow-resolution
  uint32_t shadow_memory_mib = 0;  // --shadow-memory: the shadow atlas's budget; 0: the device's default
  uint32_t shadow_updates = shadows::default_shadow_view_budget;  // --shadow-updates: views redrawn a frame
  uint32_t threads = 0;  // --threads: threads of the frame's parallel CPU work; 0: one per hardware thread
  bool shadow_cache = true;   // --shadow-cache off: redraw every map every frame
  bool shadow_layers = true;  // --shadow-layers off: no static layers, every redraw draws every caster
  LightingPath lighting = LightingPath::automatic;     // --lighting auto|forward|deferred
  LitSumStart lit_sum_start = LitSumStart::automatic;  // --lit-sum-start auto|pass|gbuffer
  float exposure = 1.0f;                               // --exposure
  LightingView view = LightingView::lit;               // --view lit|shadows
  bool animate = true;  // --animate off: glTF animations and the stress scene's orbits stand still
  // --sidecar on|off: start from <scene>.shadowgraph.json (the saved edits). On from the command
  // line; off for programs that build Options themselves (tests, tools), so a stray file in their
  // working folder cannot change what they render.
  bool sidecar = false;
  std::string script;      // --script FILE: commands instead of --frames (script.h); headless only
  std::optional<bool> ui;  // --ui on|off: the panels; unset: on in a window, off headless
  // --naive: what the source documents do, the baseline to measure against: a pass per shadow
  // view and six per cube, every map every frame, every caster in every view, forward lighting of
  // every light at every pixel.
  bool naive = false;
  std::string dump_shadow_maps;  // --dump-shadow-maps DIR: each light's map as PNG
};

// Upper bounds on the stress scene's parameters: values above them would exhaust memory
// while building the scene, so they are refused on the command line instead.
inline constexpr std::uint64_t max_scene_triangles = 100'000'000;
inline constexpr std::uint32_t max_lights_per_type = 100'000;

// Parses argv. On --help or a usage error, prints the message and returns the exit code the
// program should end with: 0 for --help, 2 for any usage error (unknown option, a value out
// of range, a malformed --camera, ...). Nothing is loaded here: --scene is checked when the
// scene is loaded.
struct ParseResult {
  std::optional<Options> options;
  int exit_code = 0;
};
ParseResult parse_options(int argc, char** argv);

// For tools that render the sandbox's frame and add options of their own: registers the
// sandbox's options on `app`, writing into `options`...
void add_options(CLI::App& app, Options& options);
// ...then parses as parse_options does (validation also from the environment). Returns nullopt
// to go on, or the exit code to end with (0 after --help, 2 for a usage error).
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, Options& options);

// The Vulkan context the options ask for (device, validation); presentation off. Callers
// include rendergraph/device/context.h, which defines the result.
vk::ContextOptions context_options(const Options& options);

}  // namespace sg::sandbox
