// SPDX-License-Identifier: MIT
#pragma once
// The sandbox's frame: the engine's (systems/frame/frame.h) with the sandbox's additions, through
// its FrameExtension: the panels (--ui; their edits in the update phase), the depth overlay
// (--depth-overlay, the render graph's extension example), the light heat map (--light-heatmap
// or the panels' switch) and the panels' pass over the picture.
#include <cstdint>
#include <memory>
#include <optional>

#include "sandbox/depth_overlay_pass.h"
#include "sandbox/light_heatmap_pass.h"
#include "sandbox/options.h"
#include "sandbox/render_scale_control.h"
#include "sandbox/ui.h"
#include "sandbox/ui_pass.h"
#include "systems/frame/frame.h"

struct GLFWwindow;

namespace sg::sandbox {

// `options` for opening the scene at `path` (a .gltf or .glb file, or a built-in scene's name) in
// a running sandbox: the same settings, the view the new scene's own (its first camera, or one
// framing it), not the command line's --camera.
Options options_to_open(Options options, const std::string& path);

class SandboxFrame {
 public:
  // `window`: the panels read their input from it (nullptr: headless, panels without input).
  SandboxFrame(vk::VulkanContext& context, SceneView& view, const Options& options, uint32_t frames_in_flight,
               GLFWwindow* window = nullptr);
  ~SandboxFrame();
  // The frame's extension calls back into this object: it stays where it was made.
  SandboxFrame(const SandboxFrame&) = delete;
  SandboxFrame& operator=(const SandboxFrame&) = delete;

  Frame& frame() { return frame_; }
  const Frame& frame() const { return frame_; }
  // The frame resized to `extent` at its render scale (render_scale_for; `window`: presented in
  // one), saying once where the scene is drawn smaller than the picture. In a CPU device's window
  // without a chosen scale, the scale adapts to the frame time (adapt_render_scale).
  void fit(VkExtent2D extent, bool window);
  // The render scale from the next fit() on (the Frame panel's): chosen, so no longer adapted.
  void set_render_scale(float scale) {
    render_scale_ = scale;
    adaptive_scale_.reset();
  }
  // Takes a frame's pass times where the render scale adapts (RenderScaleControl); returns the
  // scale the next fit() takes where it changed, and says so.
  std::optional<float> adapt_render_scale(const vk::FrameTimings& timings);
  // The render scale the last fit() took.
  float render_scale() const { return fitted_scale_; }
  // How often the adaptive render scale changed (--stats).
  uint32_t render_scale_changes() const { return render_scale_changes_; }
  // Whether the panels take the mouse or keyboard this frame (false without panels).
  bool ui_wants_input() const;
  // Lit picture or shadow-only view, from the next record() on (the panels' "view" follows).
  void set_view(LightingView view);
  // Writes the lights and camera beside the scene (scene_sidecar.h), as the panels' save does.
  void save_edits() const;
  // Writes the whole scene, its edited lights and the current view as glTF (.gltf or .glb,
  // systems/scene/gltf_export.h), saying what the file cannot keep.
  void export_gltf(const std::string& path) const;
  // The panels (nullptr without --ui).
  SandboxUi* ui() { return ui_.get(); }

 private:
  FrameExtension extension();
  UiFacts ui_facts() const;

  vk::VulkanContext& context_;
  SceneView& view_;
  std::optional<float> render_scale_;                 // --render-scale, then the Frame panel's
  std::optional<RenderScaleControl> adaptive_scale_;  // in a CPU device's window, none chosen
  uint32_t render_scale_changes_ = 0;
  float fitted_scale_ = 1.0f;
  bool render_scale_told_ = false;
  std::string scene_name_;  // --scene: where the sidecar of saved edits goes
  bool depth_overlay_enabled_;
  DepthOverlayPass depth_overlay_;
  std::optional<LightHeatmapPass> light_heatmap_;  // with --light-heatmap or the panels
  std::unique_ptr<SandboxUi> ui_;                  // with --ui
  std::unique_ptr<UiPass> ui_pass_;
  const ImDrawData* panels_ = nullptr;  // this frame's, built in the update phase
  Frame frame_;                         // last: its extension calls into the members above
};

}  // namespace sg::sandbox
