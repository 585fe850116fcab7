// SPDX-License-Identifier: MIT
#pragma once
// What the engine's frame renders and how: the picture's size, the Vulkan device, the scene and
// the view, and the renderer's settings. Each is declared once, in frame_settings_table(), with
// its command-line name, help, type and range.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "rendergraph/device/fwd.h"
#include "systems/frame/setting.h"
#include "systems/renderer/renderer_settings.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/camera.h"
#include "systems/scene/shadow_settings.h"

namespace sg {

struct FrameSettings {
  uint32_t width = 1280;  // the picture; a window's first size
  uint32_t height = 720;
  // The scene rendered at this fraction of the picture's size and scaled up into it
  // (Frame::resize); unset: render_scale_for's default.
  std::optional<float> render_scale;
  std::string device;                // a substring of the Vulkan device's name; empty: the best device
  bool validation = false;           // also on with SHADOWGRAPH_VALIDATION=1 (context_options)
  bool pipeline_statistics = false;  // vk::ContextOptions::pipeline_statistics
  std::string scene = "default";     // a built-in scene's name or a .gltf/.glb path
  // --camera: a pose, or the name of one of the scene's cameras (camera_name); neither: the
  // scene's first camera, or one framing it.
  std::optional<scene::CameraPose> camera;
  std::string camera_name;
  scene::BuiltinSceneParams scene_params;  // the stress scene's size, lights and seed
  // Start from <scene>.shadowgraph.json (saved edits, scene_sidecar.h). On from the command line
  // (command_line_defaults), off for code that fills the settings itself (tests, tools), so that
  // a stray file in its working folder cannot change what it renders.
  bool sidecar = false;
  // Every light's algorithm, set once when the scene loads (load_scene_view): the panels and
  // scripts may change it afterwards.
  std::optional<scene::ShadowAlgorithm> algorithm;
  // Every directional light's most cascades (ShadowSettings::cascades), set once as `algorithm`.
  std::optional<uint32_t> cascades;
  // Every light's contact shadow length (ShadowSettings::contact_length), set once as `algorithm`.
  std::optional<float> contact_length;
  bool animate = true;  // off: glTF animations and the stress scene's orbits stand still
  bool naive = false;   // the renderer runs naive_baseline(renderer): the source documents' frame
  RendererSettings renderer;

  // What the renderer runs: `renderer`, or with `naive` its baseline.
  RendererSettings effective_renderer() const { return naive ? naive_baseline(renderer) : renderer; }
};

// Upper bounds on the stress scene's parameters: values above them would exhaust memory while
// building the scene, so the command line refuses them.
inline constexpr uint64_t max_scene_triangles = 100'000'000;
inline constexpr uint32_t max_lights_per_type = 100'000;

// The render scale a frame on `context`'s device takes: `chosen` (FrameSettings::render_scale), or
// where unset 1, but half in a window on a CPU device, where every pixel lit costs the CPU
// (docs/PERFORMANCE.md).
float render_scale_for(std::optional<float> chosen, const vk::VulkanContext& context, bool window);

// Every frame setting, in the order the option list shows them.
std::span<const Setting<FrameSettings>> frame_settings_table();

// The settings a command line starts from: the defaults, with the sidecar on.
FrameSettings command_line_defaults();

// The Vulkan context the settings ask for (device, validation from the settings or the
// environment), presentation off. Callers include rendergraph/device/context.h, which defines it.
vk::ContextOptions context_options(const FrameSettings& settings);

}  // namespace sg
