// SPDX-License-Identifier: MIT
#include "systems/frame/frame_settings.h"

#include <cstdio>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "rendergraph/device/context.h"
#include "systems/lighting/tiled_lighting_pass.h"
#include "systems/shadows/cascades.h"

namespace sg {
namespace {

using S = FrameSettings;

// The points' coordinates, comma-separated, as --camera and --ambient take them.
std::string comma_list(std::initializer_list<glm::vec3> points) {
  std::string text;
  for (const glm::vec3& point : points) {
    for (int i = 0; i < 3; ++i) {
      if (!text.empty()) text += ',';
      text += setting_text::format(point[i]);
    }
  }
  return text;
}

// "R,G,B": three finite numbers in [0, 16].
glm::vec3 parse_ambient(const std::string& text) {
  glm::vec3 color;
  char end = 0;
  bool valid = std::sscanf(text.c_str(), "%f,%f,%f%c", &color.r, &color.g, &color.b, &end) == 3;
  for (int c = 0; valid && c < 3; ++c) valid = color[c] >= 0.0f && color[c] <= 16.0f;
  if (!valid) throw std::invalid_argument("takes three numbers from 0 to 16, R,G,B, got \"" + text + "\"");
  return color;
}

std::vector<Setting<S>> make_table() {
  // A pose's text holds commas, a camera's name none. The pose's own errors (SceneError) already
  // name --camera and the text; an unknown name is refused when the scene loads.
  Setting<S> camera{
      {"camera", "EX,EY,EZ,TX,TY,TZ|NAME",
       "eye and target, or one of the scene's cameras by name (the stress scene's: overview, "
       "street, at eye height among the lights); otherwise the scene's first camera, or one that "
       "frames the scene's bounds",
       SettingType::text},
      [](const S& s) -> std::optional<std::string> {
        if (s.camera) return comma_list({s.camera->eye, s.camera->target});
        if (!s.camera_name.empty()) return s.camera_name;
        return std::nullopt;
      },
      [](S& s, const std::string& text) {
        if (text.find(',') == std::string::npos) {
          s.camera_name = text;
        } else {
          s.camera = scene::parse_camera(text);
        }
      }};
  Setting<S> ambient{
      {"ambient", "R,G,B",
       "the ambient term per channel, linear: what a surface reflects of its base color where no "
       "light reaches",
       SettingType::text},
      [](const S& s) -> std::optional<std::string> { return comma_list({s.renderer.ambient}); },
      [](S& s, const std::string& text) { s.renderer.ambient = parse_ambient(text); }};
  Setting<S> naive = flag<S>(
      "naive", [](auto& s) -> auto& { return s.naive; },
      "the source documents' frame as a baseline: a pass per shadow view and six per cube, "
      "every map every frame, every caster in every shadow view, every light at every pixel");
  naive.info.excludes = {"lighting",     "lit-sum-start", "light-records",
                         "cube-shadows", "shadow-views",  "shadow-cache"};
  return {
      whole<S>(
          "width", "W", [](auto& s) -> auto& { return s.width; }, 1, 16384, "output width in pixels"),
      whole<S>(
          "height", "H", [](auto& s) -> auto& { return s.height; }, 1, 16384, "output height in pixels"),
      number<S>(
          "render-scale", "S", [](auto& s) -> auto& { return s.render_scale; }, 0.25, 1.0,
          "render the scene at S times the output's size and scale it up, under panels and overlays "
          "drawn at full size (default: 1; in a window on a CPU device it starts at 0.5 and follows the "
          "frame time)"),
      text<S>(
          "device", "NAME", [](auto& s) -> auto& { return s.device; },
          "use the Vulkan device whose name contains NAME (case-insensitive)"),
      flag<S>(
          "validation", [](auto& s) -> auto& { return s.validation; },
          "Khronos validation layer on (also SHADOWGRAPH_VALIDATION=1)"),
      flag<S>(
          "pipeline-statistics", [](auto& s) -> auto& { return s.pipeline_statistics; },
          "keep every pipeline's compiler statistics where the driver reports them (NVIDIA's: "
          "registers, instructions), for --stats' \"pipelines\""),
      text<S>(
          "scene", "NAME|PATH", [](auto& s) -> auto& { return s.scene; },
          "default, stress, point-room, spot-columns (one light each: a point light in a 4.7k-triangle "
          "room, a spot light on 53.7k triangles), or a .gltf/.glb file"),
      camera,
      on_off<S>(
          "sidecar", [](auto& s) -> auto& { return s.sidecar; },
          "start from the lights and camera saved beside the scene (SCENE.shadowgraph.json: the "
          "panels' save button, a script's save; for built-in scenes in the working folder)"),
      whole<S>(
          "scene-triangles", "T", [](auto& s) -> auto& { return s.scene_params.triangles; }, 1,
          max_scene_triangles, "stress scene: triangles to reach"),
      whole<S>(
          "point-lights", "N", [](auto& s) -> auto& { return s.scene_params.point_lights; }, 0,
          max_lights_per_type, "stress scene: point lights"),
      whole<S>(
          "spot-lights", "N", [](auto& s) -> auto& { return s.scene_params.spot_lights; }, 0,
          max_lights_per_type, "stress scene: spot lights"),
      number<S>(
          "moving-lights", "F", [](auto& s) -> auto& { return s.scene_params.moving_fraction; }, 0.0, 1.0,
          "stress scene: fraction of lights and crates that move each frame"),
      number<S>(
          "light-spread", "F", [](auto& s) -> auto& { return s.scene_params.light_spread; }, 0.01, 1.0,
          "stress scene: the lights spread over a square of this fraction of the hall's side, in front "
          "of the street camera (0.5: the same lights on a quarter of the floor, their reaches "
          "overlapping)"),
      whole<S>(
          "seed", "S", [](auto& s) -> auto& { return s.scene_params.seed; }, 0, UINT64_MAX,
          "stress scene: random seed (equal seeds, equal scenes)"),
      on_off<S>(
          "animate", [](auto& s) -> auto& { return s.animate; },
          "play the scene's glTF animations (node translation, rotation, scale; LINEAR, STEP, "
          "CUBICSPLINE; lights included, looping; skinned meshes stay in their bind pose) and the "
          "stress scene's orbits; headless frames advance 1/60 s each; the panels' \"play\" pauses "
          "and resumes"),
      choice<S>(
          "algorithm", [](auto& s) -> auto& { return s.algorithm; },
          "every light starts with this shadow algorithm (default: each light's own, from the "
          "scene); the light panel and scripts may change it afterwards"),
      whole<S>(
          "cascades", "N", [](auto& s) -> auto& { return s.cascades; }, 1, shadows::max_cascades,
          "every directional light starts with at most N cascaded maps over the view's depth (1: one "
          "map fitted to the whole scene; default: each light's own, 4 unless the scene says); the "
          "light panel may change it afterwards"),
      number<S>(
          "contact-shadows", "M", [](auto& s) -> auto& { return s.contact_length; }, 0.0,
          double(scene::max_contact_length),
          "every light starts with contact shadows M metres long, marched through the depth buffer "
          "toward it (0: none; default: each light's own, none unless the scene says); drawn by "
          "deferred lighting only, which CPU devices then take"),
      on_off<S>(
          "shadows", [](auto& s) -> auto& { return s.renderer.lights.shadows; },
          "off: no light casts a shadow, for comparisons"),
      choice<S>(
          "shadow-views", [](auto& s) -> auto& { return s.renderer.shadow_views; },
          "batched: the frame's due shadow views culled and drawn on the GPU in a few passes; "
          "per-light: a pass per view, casters culled on the CPU, the baseline"),
      choice<S>(
          "shadow-raster", [](auto& s) -> auto& { return s.renderer.shadow_raster; },
          "batched views rasterized by a multi-draw indirect pass or in compute (auto: on GPUs "
          "chosen each frame from the shadow passes' times recent frames measured with each; the "
          "raster hardware on CPU devices)"),
      choice<S>(
          "shadow-resolution", [](auto& s) -> auto& { return s.renderer.shadow_resolution; },
          "screen: each light's map as many texels as its reach spans on screen, at most the "
          "light's own resolution; requested: the light's own resolution wherever it is seen, to "
          "pin quality or measure a tile size at any distance"),
      whole<S>(
          "shadow-memory", "MiB", [](auto& s) -> auto& { return s.renderer.shadow_memory_mib; }, 0, 1u << 20,
          "the shadow atlas's budget (0: an eighth of the GPU's memory, 64 to 2048 MiB); over it the least "
          "important lights lose resolution, then their shadow"),
      whole<S>(
          "shadow-updates", "N", [](auto& s) -> auto& { return s.renderer.shadow_view_budget; }, 0, 1u << 24,
          "shadow views (2D maps, cube faces) redrawn per frame at most, stalest first (0: every "
          "view due)"),
      number<S>(
          "shadow-budget-ms", "MS", [](auto& s) -> auto& { return s.renderer.shadow_budget_ms; }, 0.0, 1000.0,
          "GPU time the shadow passes may take a frame, learnt from recent frames' timestamps: over it "
          "lights lose resolution by their size on screen down to their quality floor, then map redraws "
          "wait their turn, stalest first (0: no budget; default: 6 on GPUs, none on CPU devices); "
          "--shadow-memory still caps on top"),
      choice<S>(
          "shadow-time-policy", [](auto& s) -> auto& { return s.renderer.shadow_time_policy; },
          "how --shadow-budget-ms lowers resolutions: redraw-cost spares maps by how seldom they are "
          "redrawn (a map kept from frame to frame costs no time); uniform lowers every light alike"),
      whole<S>(
          "filtered-shadows", "N", [](auto& s) -> auto& { return s.renderer.filtered_lights; }, 0,
          TiledLightingPass::most_filtered_lights,
          "deferred lighting: at each pixel the N lights that add most to it run their shadow filter "
          "(pcf, noise, pcss); lighter ones take the hard test, which bounds the cost where many "
          "lights overlap (0: every light filters; default: 8 on GPUs, every light on CPU devices)"),
      on_off<S>(
          "shadow-cache", [](auto& s) -> auto& { return s.renderer.cache_shadows; },
          "on: a map is redrawn only when its light, or a caster in its reach, moved; off: every "
          "map every frame"),
      on_off<S>(
          "shadow-layers", [](auto& s) -> auto& { return s.renderer.static_shadow_layers; },
          "compute raster: keep each map's still casters as a layer (twice the shadow memory) and "
          "redraw moving casters alone over it"),
      choice<S>(
          "cube-shadows", [](auto& s) -> auto& { return s.renderer.cube_shadows; },
          "per-light views: a point light's cube in one pass (layered) or six"),
      whole<S>(
          "threads", "N", [](auto& s) -> auto& { return s.renderer.cpu_threads; }, 0, 1024,
          "threads for the frame's CPU work split in pieces (gathering, shadow scheduling), the "
          "frame's own included (0: one per hardware thread)"),
      choice<S>("lighting", [](auto& s) -> auto& { return s.renderer.lighting; },
                "deferred: G-buffer, light lists, a pass per light group; fused: depth prepass and one "
                "forward pass of every light that tone-maps too (auto: deferred on GPUs; on CPU devices "
                "chosen each frame, fused for up to four lights and 8,192 triangles, deferred for more)",
                {"auto", "deferred", "fused"}),
      choice<S>(
          "lit-sum-start", [](auto& s) -> auto& { return s.renderer.lit_sum_start; },
          "where deferred lighting starts the lit sum (ambient term, background): a full-screen "
          "pass, or a G-buffer target (auto: the G-buffer on CPU devices, the pass on GPUs)"),
      on_off<S>(
          "group-sets", [](auto& s) -> auto& { return s.renderer.group_sets; },
          "deferred lighting on CPU devices: a tile whose light groups (a few, one light each) are "
          "one of the frame's commonest sets takes one pass for them all, not one a group"),
      choice<S>(
          "pipeline-builds", [](auto& s) -> auto& { return s.renderer.pipeline_builds; },
          "when the group sets' pipelines are built (about a second each on lavapipe): background, on a "
          "thread of their own while frames go on without them; in-frame, by the frame that first "
          "takes a set, so that a run's pictures are the same every time"),
      choice<S>(
          "light-records", [](auto& s) -> auto& { return s.renderer.light_records; },
          "how deferred lighting reads the light records: from a storage buffer, or through a "
          "texel buffer (auto: storage on GPUs, texel on CPU devices, whose storage loads go lane "
          "by lane)"),
      ambient,
      number<S>(
          "exposure", "E", [](auto& s) -> auto& { return s.renderer.exposure; }, 1e-3, 1e3,
          "multiplies the lit color before tone mapping"),
      choice<S>(
          "view", [](auto& s) -> auto& { return s.renderer.view; },
          "shadows: a debug view of white diffuse surfaces under white lights, each light's "
          "shadow at full density, no ambient"),
      naive,
  };
}

}  // namespace

std::span<const Setting<FrameSettings>> frame_settings_table() {
  static const std::vector<Setting<FrameSettings>> table = make_table();
  return table;
}

FrameSettings command_line_defaults() {
  FrameSettings settings;
  settings.sidecar = true;
  return settings;
}

float render_scale_for(std::optional<float> chosen, const vk::VulkanContext& context, bool window) {
  if (chosen) return *chosen;
  // On lavapipe (2-core VM) `default` takes 131-135 ms a frame at 1280x720 and 45-46 at half
  // scale (2026-12-05): a window at full size is not interactive there.
  return window && context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 0.5f : 1.0f;
}

vk::ContextOptions context_options(const FrameSettings& settings) {
  vk::ContextOptions context;
  context.validation = settings.validation || vk::validation_requested_by_environment();
  context.device_name = settings.device;
  context.pipeline_statistics = settings.pipeline_statistics;
  return context;
}

}  // namespace sg
