// SPDX-License-Identifier: MIT
#include "sandbox/sandbox_frame.h"

#include <cstdio>
#include <exception>
#include <filesystem>

#include "rendergraph/device/context.h"
#include "rendergraph/vulkan/graph_executor.h"
#include "systems/frame/scene_sidecar.h"
#include "systems/scene/gltf_export.h"

namespace sg::sandbox {

Options options_to_open(Options options, const std::string& path) {
  options.frame.scene = path;
  options.frame.camera.reset();
  options.frame.camera_name.clear();
  return options;
}

SandboxFrame::SandboxFrame(vk::VulkanContext& context, SceneView& view, const Options& options,
                           uint32_t frames_in_flight, GLFWwindow* window)
    : context_(context),
      view_(view),
      render_scale_(options.frame.render_scale),
      scene_name_(options.frame.scene),
      depth_overlay_enabled_(options.depth_overlay),
      depth_overlay_(context, frame_format),
      frame_(context, view, options.frame, frames_in_flight, {extension()}) {
  // The panels switch the heat map on and off, so with them it is always ready.
  const bool panels = options.ui.value_or(window != nullptr);
  if (options.light_heatmap || panels) light_heatmap_.emplace(context, frame_format);
  if (panels) {
    ui_ = std::make_unique<SandboxUi>(window);
    ui_->set_playing(options.frame.animate);
    ui_->set_view(options.frame.renderer.view);
    ui_->set_ambient(options.frame.renderer.ambient);
    ui_->set_max_fps(float(options.max_fps));
    ui_->set_light_heatmap(options.light_heatmap);
    ui_->set_shadow_budgets(frame_.renderer().shadow_view_budget(),
                            frame_.renderer().shadow_time_budget_ms());
    ui_pass_ = std::make_unique<UiPass>(context, frame_format, frames_in_flight);
  }
}

SandboxFrame::~SandboxFrame() = default;

void SandboxFrame::fit(VkExtent2D extent, bool window) {
  // Where none was chosen, a scale under 1 (a CPU device's window) follows the frame time from there.
  const float given = render_scale_for(render_scale_, context_, window);
  if (!render_scale_ && !adaptive_scale_ && given < 1.0f) adaptive_scale_.emplace(given);
  const float scale = adaptive_scale_ ? adaptive_scale_->scale() : given;
  frame_.resize(extent, scale);
  fitted_scale_ = scale;
  if (ui_) ui_->set_render_scale(scale);
  if (scale < 1.0f && !render_scale_told_) {
    const VkExtent2D scene = frame_.scene_extent();
    std::printf("shadowgraph: the scene is rendered at %ux%u and scaled up to %ux%u (--render-scale %g%s)\n",
                scene.width, scene.height, extent.width, extent.height, double(scale),
                adaptive_scale_
                    ? ", the start in a window on a CPU device, where the scale follows the frame "
                      "time; choose one to hold it"
                    : "");
    render_scale_told_ = true;
  }
}

std::optional<float> SandboxFrame::adapt_render_scale(const vk::FrameTimings& timings) {
  if (!adaptive_scale_) return std::nullopt;
  // The scene's passes are those before its upscale into the frame.
  double frame_ms = 0.0;
  double scene_ms = 0.0;
  bool scene = true;
  for (size_t p = 0; p < timings.pass_ms.size(); ++p) {
    if (timings.plan->passes[p].name == upscale_pass_name) scene = false;
    frame_ms += timings.pass_ms[p];
    if (scene) scene_ms += timings.pass_ms[p];
  }
  const float before = adaptive_scale_->scale();
  const std::optional<float> scale = adaptive_scale_->take_frame(frame_ms, scene_ms);
  if (scale) {
    ++render_scale_changes_;
    std::printf(
        "shadowgraph: render scale %g -> %g: the GPU frame took %.1f ms (median of %zu frames) "
        "against a budget of %g ms\n",
        double(before), double(*scale), adaptive_scale_->judged_ms(), RenderScaleControl::window,
        adaptive_scale_->budget_ms());
  }
  return scale;
}

FrameExtension SandboxFrame::extension() {
  FrameExtension extension;
  extension.update = [this](double seconds) {
    if (!ui_) return;
    panels_ =
        ui_->build(view_.scene, view_.pose, ui_facts(), frame_.image().extent(), static_cast<float>(seconds));
    if (ui_->take_save_request()) save_edits();
    if (ui_->take_export_request()) {
      try {
        export_gltf(scene_name_ + ".edited.glb");
      } catch (const std::exception& error) {  // a panel's button must not end the run
        std::fprintf(stderr, "shadowgraph: export failed: %s\n", error.what());
      }
    }
    frame_.renderer().set_view(ui_->view());
    frame_.renderer().set_ambient(ui_->ambient());
    frame_.renderer().set_shadow_budgets(ui_->shadow_view_budget(), ui_->shadow_time_budget_ms());
    frame_.set_playing(ui_->playing());
  };
  extension.prepare = [this](uint32_t slot) {
    if (ui_pass_) ui_pass_->prepare(slot, panels_, ui_->depth_views());
  };
  extension.add_passes = [this](rg::RenderGraph& graph, const RenderedFrame& rendered, rg::ImageHandle color,
                                uint32_t slot) {
    if (depth_overlay_enabled_) color = depth_overlay_.add_to(graph, rendered.depth, color, view_.lens);
    const bool heatmap = ui_ ? ui_->light_heatmap() : light_heatmap_.has_value();
    if (heatmap && rendered.light_tiles)
      color = light_heatmap_->add_to(graph, *rendered.light_tiles, rendered.depth, color);
    if (ui_pass_) color = ui_pass_->add_to(graph, color, rendered.shadow_atlas, slot);
    return color;
  };
  return extension;
}

bool SandboxFrame::ui_wants_input() const { return ui_ && ui_->wants_input(); }

void SandboxFrame::set_view(LightingView view) {
  frame_.renderer().set_view(view);
  if (ui_) ui_->set_view(view);
}

void SandboxFrame::save_edits() const {
  const std::filesystem::path path = sidecar_path(scene_name_);
  save_sidecar(path, view_.scene, view_.pose);
  std::printf("shadowgraph: saved the lights and camera to %s\n", path.string().c_str());
}

void SandboxFrame::export_gltf(const std::string& path) const {
  const scene::ExportReport report =
      scene::export_gltf(view_.scene, scene::ExportView{view_.pose, view_.lens}, path);
  std::printf("shadowgraph: exported the scene to %s (%zu nodes, %zu meshes, %zu lights)\n", path.c_str(),
              report.nodes, report.meshes, report.lights);
  if (report.animated_entities > 0) {
    std::printf(
        "shadowgraph: warning: %zu animated entities were written where they stand now; glTF export keeps "
        "no animation\n",
        report.animated_entities);
  }
}

UiFacts SandboxFrame::ui_facts() const {
  UiFacts facts;
  facts.cpu_frame_ms = frame_.last_cpu_ms();
  if (const std::optional<vk::FrameTimings>& timings = frame_.executor().latest_timings()) {
    for (size_t p = 0; p < timings->pass_ms.size(); ++p) {
      facts.gpu_frame_ms += timings->pass_ms[p];
      facts.passes.emplace_back(timings->plan->passes[p].name, timings->pass_ms[p]);
    }
  }
  const SceneRenderer& renderer = frame_.renderer();
  const shadows::ShadowScheduleStats& shadows = renderer.shadow_stats();
  facts.views_rendered = shadows.views_rendered;
  facts.views_cached = shadows.views_cached;
  facts.views_moving_only = shadows.views_moving_only;
  facts.map_lag_p99 = shadows.map_lag_p99;
  facts.map_lag_max = shadows.map_lag_max;
  facts.lights_without_shadow = shadows.lights_without_shadow;
  facts.lights = static_cast<uint32_t>(renderer.lights().records.size());
  facts.shadow_mib = double(renderer.shadow_atlas().bytes()) / (1 << 20);
  facts.lighting = to_string(renderer.lighting());
  facts.scene_extent = frame_.scene_extent();
  facts.frame_lights = &renderer.lights();
  facts.atlas_page = renderer.shadow_atlas().shape().page_size;
  facts.atlas_pages = renderer.shadow_atlas().pages();
  if (context_.validation_enabled()) facts.validation_errors = context_.validation_errors();
  return facts;
}

}  // namespace sg::sandbox
