// SPDX-License-Identifier: MIT
#pragma once
// The sandbox's panels, with Dear ImGui: frame facts (CPU and GPU time, shadow views drawn and
// kept, shadow memory) and a light editor (pick a light by type and name; edit its position,
// color, intensity, range, cone, and every shadow setting: algorithm, biases, PCF radius, light
// size, density, shadow color, resolution, layer masks; add and remove lights; orbit or bob them;
// play or pause animation) and a mesh editor (MeshPanel). Edits are writes to the ECS world like
// any system's, so change ticks and the shadow cache see them. UiPass draws the result.
//
// One SandboxUi per ImGui context; with a window, ImGui reads its input through GLFW (the
// installed callbacks chain to the window's own); headless, the panels are drawn without input.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "ecs/entity.h"
#include "ecs/world.h"
#include "sandbox/mesh_panel.h"
#include "systems/lighting/lighting_path.h"
#include "systems/scene/aabb.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/frame_lights.h"

struct GLFWwindow;
struct ImDrawData;
struct ImGuiContext;

namespace sg::sandbox {

// A shadow map a panel shows: an atlas layer's depth as grey (UiPass), drawn by ImGui::Image
// with texture id (index in SandboxUi::depth_views() + 1) and the tile as uv rectangle.
struct UiDepthView {
  uint32_t layer = 0;
  float near = 0.0f;  // perspective maps: their depth range, to make depth linear again
  float far = 1.0f;
  bool linear = true;  // orthographic maps and cube faces store linear depth already
};

// What the panels show; the frame gathers it.
struct UiFacts {
  const shadows::FrameLights* frame_lights = nullptr;  // the last frame's, for the selected light's map
  uint32_t atlas_page = 0;                             // texels a side of an atlas layer
  uint32_t atlas_pages = 0;                            // layers of the atlas
  std::optional<uint32_t> validation_errors;           // unset with the validation layer off
  std::vector<std::pair<std::string, double>> passes;  // GPU ms per pass, newest timed frame
  double cpu_frame_ms = 0.0;
  double gpu_frame_ms = 0.0;  // the newest frame whose timings are back; 0 when unknown
  uint32_t views_rendered = 0;
  uint32_t views_cached = 0;
  uint32_t views_moving_only = 0;  // of views_rendered, over their static layers
  uint32_t map_lag_p99 = 0;        // frames the due maps had been wrong (ShadowScheduleStats)
  uint32_t map_lag_max = 0;
  uint32_t lights = 0;
  uint32_t lights_without_shadow = 0;
  double shadow_mib = 0.0;
  std::string lighting;
  VkExtent2D scene_extent{};  // what the scene is drawn at (Frame::scene_extent)
};

class SandboxUi {
 public:
  explicit SandboxUi(GLFWwindow* window);  // nullptr: headless
  ~SandboxUi();
  SandboxUi(const SandboxUi&) = delete;
  SandboxUi& operator=(const SandboxUi&) = delete;

  // Builds this frame's panels for a `size` frame, applying the user's edits to `scene` (new
  // lights go in front of `pose`), and returns what to draw (valid until the next build).
  const ImDrawData* build(scene::Scene& scene, const scene::CameraPose& pose, const UiFacts& facts,
                          VkExtent2D size, float seconds);

  // Whether the panels take the mouse or keyboard this frame (the fly camera then keeps still).
  bool wants_input() const;

  // True once after the user pressed "save" (the frame writes the sidecar, scene_sidecar.h).
  bool take_save_request() { return std::exchange(save_requested_, false); }
  // The path typed into the Frame panel's "open", once, after the user pressed its button.
  std::optional<std::string> take_open_request() { return std::exchange(open_request_, std::nullopt); }
  // True once after the user pressed "export glTF" (the frame writes SCENE.edited.glb).
  bool take_export_request() { return std::exchange(export_requested_, false); }

  // What the user would pick in the panels; for tests and scripted runs.
  void select(ecs::Entity light) { selected_ = light; }
  void show_map(bool show) { show_map_ = show; }

  // The picture the panel's "view" asks for (the frame starts it from --view).
  LightingView view() const { return static_cast<LightingView>(view_); }
  void set_view(LightingView view) { view_ = static_cast<int>(view); }
  // The Frame panel's frame-rate cap (FramePacer, 0: none).
  float max_fps() const { return max_fps_; }
  void set_max_fps(float fps) { max_fps_ = fps; }
  // The Frame panel's render scale (Frame::resize): the one in use, and a new one once its
  // slider is let go.
  void set_render_scale(float scale) { render_scale_ = scale; }
  std::optional<float> take_render_scale_request() {
    return std::exchange(render_scale_request_, std::nullopt);
  }
  // The Frame panel's shadow budgets (SceneRenderer::set_shadow_budgets).
  uint32_t shadow_view_budget() const { return uint32_t(shadow_view_budget_); }
  double shadow_time_budget_ms() const { return shadow_time_budget_ms_; }
  void set_shadow_budgets(uint32_t view_budget, double time_budget_ms) {
    shadow_view_budget_ = int(view_budget);
    shadow_time_budget_ms_ = time_budget_ms;
  }
  // The Frame panel's ambient term (RendererSettings::ambient).
  const glm::vec3& ambient() const { return ambient_; }
  void set_ambient(const glm::vec3& ambient) { ambient_ = ambient; }

  // Whether the light-count heat map is drawn (the panel's checkbox; from --light-heatmap).
  bool light_heatmap() const { return light_heatmap_; }
  void set_light_heatmap(bool on) { light_heatmap_ = on; }

  // Whether animation plays (the panel's "play"; the frame starts it from --animate).
  bool playing() const { return playing_; }
  void set_playing(bool playing) { playing_ = playing; }

  // What F frames: the selected light's reach (range clamped to 1..10 m, 1 m without one), or
  // an empty box when no light is selected.
  scene::Aabb selection_bounds(const ecs::World& world) const;

  // The shadow maps the last build() showed.
  const std::vector<UiDepthView>& depth_views() const { return depth_views_; }

 private:
  void stats_panel(const UiFacts& facts);
  void light_panel(scene::Scene& scene, const scene::CameraPose& pose, const UiFacts& facts);
  void help_panel();
  void shadow_map_panel(const ecs::World& world, const UiFacts& facts);

  ImGuiContext* context_ = nullptr;
  bool glfw_ = false;
  int type_filter_ = 0;  // 0 all, then point, spot, directional, cylinder
  int order_ = 0;        // 0 the scene's, 1 by name, 2 by importance (largest on screen first)
  scene::ShadowAlgorithm all_algorithm_ = scene::ShadowAlgorithm::pcf;  // the last one given to all
  std::vector<std::pair<ecs::Entity, float>> listed_;                   // this frame's list, with importance
  ecs::Entity selected_ = ecs::null_entity;
  std::array<float, 120> gpu_history_{};  // ms, a ring
  size_t history_next_ = 0;
  bool help_ = false;
  bool show_map_ = false;
  bool save_requested_ = false;
  bool export_requested_ = false;
  std::array<char, 512> open_path_{};
  std::optional<std::string> open_request_;
  float render_scale_ = 1.0f;
  std::optional<float> render_scale_request_;
  bool playing_ = true;
  int view_ = 0;  // a LightingView
  glm::vec3 ambient_{0.0f};
  float max_fps_ = 0.0f;
  int shadow_view_budget_ = 0;
  double shadow_time_budget_ms_ = 0.0;  // a double, as the renderer's: what it set comes back unchanged
  bool light_heatmap_ = false;
  std::vector<UiDepthView> depth_views_;
  MeshPanel meshes_;
};

}  // namespace sg::sandbox
