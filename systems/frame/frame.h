// SPDX-License-Identifier: MIT
#pragma once
// The engine's frame. record() runs the frame's five phases, in this order and nowhere else:
//
//   1. update   systems that write the world: the application's edits (FrameExtension::update),
//               animation, then world transforms
//   2. gather   read-only systems over a const World: drawables and lights into CPU lists
//   3. prepare  shadow storage, caster culling, this frame slot's GPU buffers and descriptors
//   4. declare  the frame graph: shadow passes, lighting (SceneRenderer) -> [the extensions'
//               passes over the picture, in their order] -> [present, to a swapchain image]
//   5. execute  compile (plans come from a PlanCache: shapes repeat) and record the commands
//
// The picture lands in the persistent "frame" image (imported into each graph, left in
// TRANSFER_SRC), which screenshots read and the present pass blits to the swapchain image.
//
//   SceneView view = load_scene_view(settings, aspect);
//   vk::FrameRing ring(context);
//   Frame frame(context, view, settings, ring.frames_in_flight());
//   frame.resize({settings.width, settings.height});
//   frame.record(frame.begin(ring), seconds);
//   ring.submit();
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/plan_cache.h"
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/graph_executor.h"
#include "rendergraph/vulkan/graph_imports.h"
#include "systems/frame/depth_capture.h"
#include "systems/frame/frame_settings.h"
#include "systems/frame/scene_view.h"
#include "systems/renderer/scene_renderer.h"

namespace sg {

// A swapchain image to present this frame on. The submission must wait for its acquire
// semaphore at `acquire_wait_stage`.
struct PresentTarget {
  VkImage image = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{};
};
inline constexpr VkPipelineStageFlags2 acquire_wait_stage = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;

// The frame image's format: what screenshots read and the present pass blits.
inline constexpr rg::Format frame_format = rg::Format::rgba8_srgb;
// The pass that scales the renderer's picture up into the frame where the render scale is under
// 1 (Frame::resize): the passes before it draw the scene at its size, those after at the frame's.
inline constexpr const char* upscale_pass_name = "upscale";

// What an application or a library adds to the frame without editing it (the sandbox: its panels
// and overlays; sandbox/examples/custom_pass: a pass of its own, built against the installed
// engine); each member is optional. A frame takes a list of them and calls each phase's in order.
struct FrameExtension {
  // In the update phase, before the systems: `seconds` since the last frame.
  std::function<void(double seconds)> update;
  // In the prepare phase, after the renderer's.
  std::function<void(uint32_t slot)> prepare;
  // In the declare phase: passes over the picture `color` (the lit, tone-mapped frame image, or
  // the version the extension before wrote), returning its newest version. `rendered` names the
  // frame's other images: its depth buffer, the shadow atlas, the light lists.
  std::function<rg::ImageHandle(rg::RenderGraph& graph, const RenderedFrame& rendered, rg::ImageHandle color,
                                uint32_t slot)>
      add_passes;
};

class Frame {
 public:
  // Renders `view` (kept by reference: the application may move the camera and edit the world
  // between frames) with `settings`' renderer settings and animation.
  Frame(vk::VulkanContext& context, SceneView& view, const FrameSettings& settings, uint32_t frames_in_flight,
        std::vector<FrameExtension> extensions = {});

  // (Re)creates the frame image at `extent`. The scene is rendered at `render_scale` (0 to 1] of
  // it (scene_extent) and scaled up into it before the extensions' passes, which draw at the
  // frame's own size: a CPU device's window keeps its panels sharp while a quarter of the pixels
  // are lit. The GPU must not be using the old image (wait idle first).
  void resize(VkExtent2D extent, float render_scale = 1.0f);
  // What the renderer draws: the frame image's extent times the render scale, at least 1x1.
  VkExtent2D scene_extent() const { return scene_extent_; }

  // ring.begin_frame(), waking the worker threads of record()'s batches shortly before the wait
  // for the GPU ends: asleep since the last frame, they took longer to wake than the frame's
  // first batches take to run.
  vk::FrameSlot& begin(vk::FrameRing& ring);
  // Runs the frame's phases for the scene at `time_seconds` and records the commands into
  // `frame.cmd`.
  void record(const vk::FrameSlot& frame, double time_seconds,
              const std::optional<PresentTarget>& present = std::nullopt);

  // Whether animation advances with time (the settings' animate to start with).
  bool playing() const { return playing_; }
  void set_playing(bool playing) { playing_ = playing; }

  const vk::Image& image() const { return image_; }
  SceneRenderer& renderer() { return renderer_; }
  const SceneRenderer& renderer() const { return renderer_; }
  const rg::RenderGraph& graph() const { return graph_; }
  const std::shared_ptr<const rg::CompiledPlan>& plan() const { return plan_; }
  vk::GraphExecutor& executor() { return executor_; }
  const vk::GraphExecutor& executor() const { return executor_; }
  // From the next record() on, each frame also copies the camera's depth buffer into an image
  // kept after the frame (depth_capture.h), which read_captured_depth returns once the frame's
  // commands have completed.
  void capture_depth() { depth_capture_.emplace(); }
  vk::DepthImage read_captured_depth() const;

  // Per recorded frame: CPU milliseconds of each phase of record(), of the renderer's steps
  // within gather and prepare (SceneRenderer::CpuSteps), and of the shadow schedule's steps
  // (shadows::ScheduleStep) within its schedule step.
  struct PhaseTimes {
    std::vector<double> update, gather, prepare, declare, execute;
    std::vector<double> instances, lights, schedule, upload, views;
    std::array<std::vector<double>, shadows::schedule_step_count> schedule_steps;
  };
  const PhaseTimes& phase_ms() const { return phase_ms_; }
  // The last recorded frame's CPU milliseconds, all phases.
  double last_cpu_ms() const;
  // Per recorded frame: shadow views (2D maps, cube faces) drawn, and kept from earlier frames.
  const std::vector<double>& shadow_views_rendered() const { return shadow_views_rendered_; }
  // Per frame: the (tile, light) pairs the light lists held (SceneRenderer::light_list_pairs).
  const std::vector<double>& light_list_pairs() const { return light_list_pairs_; }
  const std::vector<double>& shadow_views_cached() const { return shadow_views_cached_; }
  const std::vector<double>& shadow_views_moving_only() const { return shadow_views_moving_only_; }
  // Per recorded frame, the maps over time (shadows::ShadowScheduleStats): how many frames the
  // due maps had been wrong (median, 99th percentile, most over those lights; 0 in frames with
  // none due), the lights whose resolution changed and those given other tiles; and the frames
  // whose atlas was repacked.
  struct MapTimeline {
    std::vector<double> lag_p50, lag_p99, lag_max, lights_changed_tier, lights_retiled;
    uint64_t atlas_repacks = 0;
  };
  const MapTimeline& map_timeline() const { return map_timeline_; }
  // The number (vk::Frame::frame_number, counted over the frame ring's run) of the first recorded
  // frame in which no shadowed light waited for its first map: every one had a map to sample, if
  // a stale one. Until then some lights were lit without a shadow and the frames drew views a
  // settled run does not, so a run's figures from there on are what it settles at. Unset while
  // lights wait.
  std::optional<uint64_t> first_maps() const { return first_maps_; }
  // With the GPU idle: the (tile, light) pairs the light lists of the frames recorded so far had
  // no room for (SceneRenderer::dropped_light_pairs), counted from zero again after.
  uint64_t take_dropped_light_pairs();
  // What the shadow budgets did: per timed frame, its shadow passes' GPU milliseconds; per
  // recorded frame, what each budget held down (shadows::ShadowScheduleStats), and how many frames
  // each held down at all.
  struct ShadowBudgetRecord {
    std::vector<double> shadow_ms;
    std::vector<double> lights_demoted_by_time, views_deferred_by_time;
    std::vector<double> lights_demoted_by_memory, lights_dropped_by_memory;
    uint64_t frames_bound_by_time = 0;
    uint64_t frames_bound_by_memory = 0;
  };
  const ShadowBudgetRecord& shadow_budget_record() const { return shadow_budget_; }

 private:
  // Advances the animation clock by `seconds` while animation plays, then runs the systems.
  void update(double seconds);
  void declare_passes(uint32_t slot, const std::optional<PresentTarget>& present);
  // Hands the renderer the latest timed frame's pass times with the shadow work it drew (the
  // automatic raster choice and the time budget learn from them).
  void report_shadow_time();
  // Adds the prepared frame's shadow budget effects to shadow_budget_.
  void record_shadow_budgets(const shadows::ShadowScheduleStats& shadows);
  void execute(const vk::FrameSlot& frame);

  vk::VulkanContext& context_;
  SceneView& view_;
  std::vector<FrameExtension> extensions_;
  bool playing_;
  double animation_seconds_ = 0.0;  // advances only while animation plays
  double last_time_seconds_ = 0.0;
  SceneRenderer renderer_;
  std::optional<DepthCapture> depth_capture_;  // after capture_depth()
  vk::GraphExecutor executor_;
  rg::PlanCache plans_;
  vk::GraphImports imports_;
  vk::Image image_;
  VkExtent2D scene_extent_{};
  std::optional<vk::Image> scene_image_;  // the renderer's picture where it is smaller than the frame
  ecs::Tick transforms_updated_ = 0;
  rg::RenderGraph graph_;
  std::shared_ptr<const rg::CompiledPlan> plan_;
  PhaseTimes phase_ms_;
  std::vector<double> shadow_views_rendered_;
  std::vector<double> light_list_pairs_;
  std::vector<double> shadow_views_cached_;
  std::vector<double> shadow_views_moving_only_;
  MapTimeline map_timeline_;
  std::optional<uint64_t> first_maps_;
  uint64_t dropped_light_pairs_ = 0;
  ShadowBudgetRecord shadow_budget_;
  // The shadow work the last frames drew, by frame number, until their timings come back.
  struct DrawnViews {
    uint64_t frame = UINT64_MAX;
    SceneRenderer::ShadowWork work;
  };
  std::array<DrawnViews, 8> drawn_views_;
  uint64_t reported_frame_ = UINT64_MAX;
};

}  // namespace sg
