// SPDX-License-Identifier: MIT
#pragma once
// Renders an ECS scene through the render graph: the shadow maps due this frame, the lighting
// (lighting_path.h), then exposure and tone mapping into the frame. It takes three of the
// frame's phases (Frame::record, systems/frame/frame.h, names all five):
//
//   renderer.gather(world);                       // read the world: drawables and lights, on the CPU
//   renderer.prepare(slot, pose, lens, w, h);     // shadow tiles and caching, this slot's GPU buffers
//   RenderedFrame f = renderer.add_passes(graph, imports, frame, slot, pose, lens);
//
// `frame` is any color image of a format given at construction (imported or transient); the
// returned handles let later passes (overlays, copies, presentation) read the results. The
// shadow atlas is imported through `imports` as "shadow atlas".
#include <cstdint>
#include <optional>

#include "ecs/jobs/thread_pool.h"
#include "ecs/world.h"
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/vulkan/graph_imports.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/lighting/depth_prepass.h"
#include "systems/lighting/forward_pass.h"
#include "systems/lighting/fused_forward_pass.h"
#include "systems/lighting/gbuffer_pass.h"
#include "systems/lighting/light_record_upload.h"
#include "systems/lighting/light_tiles_pass.h"
#include "systems/lighting/tiled_lighting_pass.h"
#include "systems/lighting/tone_map_pass.h"
#include "systems/lighting/transparent_pass.h"
#include "systems/renderer/renderer_settings.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene.h"
#include "systems/shadow_maps/shadow_atlas.h"
#include "systems/shadow_maps/shadow_passes.h"
#include "systems/shadow_maps/shadow_view_batch.h"
#include "systems/shadows/frame_lights.h"
#include "systems/shadows/shadow_schedule.h"

namespace sg {

struct RenderedFrame {
  rg::ImageHandle color;         // the frame image's newest version: the tone-mapped picture
  rg::ImageHandle depth;         // the camera's D32 depth buffer (transient)
  rg::ImageHandle shadow_atlas;  // every shadow map, this frame's newest version
  // The tiled paths' light lists (invalid handles with --naive's every-light forward).
  std::optional<LightTiles> light_tiles;
};

class SceneRenderer {
 public:
  // Uploads `scene`'s meshes and textures; the scene's world is read by gather() each frame.
  // `frame_format` is the format of the images add_passes draws the picture into.
  SceneRenderer(vk::VulkanContext& context, const scene::Scene& scene, uint32_t frames_in_flight,
                rg::Format frame_format, const RendererSettings& settings = {});

  // Reads the world's drawables and lights into CPU lists. Transforms must be up to date. Once a
  // frame, each followed by prepare(): the shadow schedule learns what moved from the last gather
  // alone.
  void gather(const ecs::World& world);
  // Gives the gathered lights their shadow tiles (their importance measured from the camera
  // `pose` and `lens` on a `width` x `height` frame), decides which maps are redrawn, and writes
  // everything the frame's passes read into the slot's buffers and descriptor sets. Call after
  // FrameRing::begin_frame gave `slot`.
  void prepare(uint32_t slot, const scene::CameraPose& pose, const scene::Camera& lens, uint32_t width,
               uint32_t height);
  // Declares the shadow passes, the lighting and the tone mapping into `frame`.
  RenderedFrame add_passes(rg::RenderGraph& graph, vk::GraphImports& imports, rg::ImageHandle frame,
                           uint32_t slot, const scene::CameraPose& pose, const scene::Camera& lens);

  // The lighting path in use: the settings' one, or for automatic the one chosen for the device.
  // The last prepared frame's (automatic resolved).
  LightingPath lighting() const { return lighting_; }
  const GpuScene& gpu_scene() const { return gpu_scene_; }
  const shadows::FrameLights& lights() const { return lights_; }
  // The (tile, light) pairs the light lists' pool had no room for in the frame read back in the
  // last prepare (frames in flight ago): lights missing from some tiles' lighting.
  uint64_t dropped_light_pairs() const { return dropped_light_pairs_; }
  // Over the frames read back so far, the tiles whose lists a CPU driver's guard against endless
  // loops cut short (LightTilesPass::tiles_cut): lights are missing from them.
  uint64_t light_tiles_cut() const { return light_tiles_cut_; }
  // The last prepared frame's lights whose contact shadows were not drawn: all of them on a path
  // other than deferred, the only one that reads the depth buffer they march through.
  uint32_t contact_shadows_skipped() const { return contact_shadows_skipped_; }
  // The (tile, light) pairs the opaque surfaces' light lists held in that frame, dropped ones
  // included (LightTilesPass::listed_pairs); none before a frame was read back, or without
  // tiled lighting.
  std::optional<uint64_t> light_list_pairs() const;
  // Deferred lighting's ranked filtering: at each pixel the most lights that run their filter
  // kernels (TiledLightingPass); 0: every light, and always without tile lists.
  uint32_t filtered_lights() const { return deferred_ ? deferred_->lighting.filtered_lights() : 0u; }
  // With the GPU idle: the pairs the frames not read back yet left out (every slot's).
  uint64_t drain_dropped_light_pairs();
  // Waits for the pipelines being built in the background (RendererSettings::pipeline_builds):
  // the next frame takes every one asked for, as an in-frame build would have had it.
  void wait_for_pipeline_builds() {
    if (deferred_) deferred_->lighting.wait_for_pipeline_builds();
  }
  const ShadowAtlas& shadow_atlas() const { return atlas_; }
  const shadows::ShadowScheduleStats& shadow_stats() const { return schedule_.stats(); }
  // How long the shadow schedule's steps took in the last prepare().
  const shadows::ScheduleStepTimes& schedule_step_times() const { return schedule_.step_times(); }
  // The path in use: the settings' one, or per-light where batching is not supported.
  shadows::ShadowViewPath shadow_views() const {
    return batch_ ? shadows::ShadowViewPath::batched : shadows::ShadowViewPath::per_light;
  }
  // The batched path's raster (never automatic); unset on the per-light path.
  std::optional<shadows::ShadowRaster> shadow_raster() const {
    return batch_ ? std::optional(batch_->raster()) : std::nullopt;
  }
  // Whether the 2D kernels' hardware comparisons each filter a bilinear 2x2 or compare the
  // nearest texel, on devices that cannot filter the atlas's depth format (lavapipe).
  bool shadow_comparisons_filtered() const { return shadow_comparisons_filter(context_); }
  // Caster instances drawn into shadow views: the batch's count (read back a few frames late) or
  // the per-light passes' CPU culling.
  uint64_t shadow_caster_draws() const;
  const RendererSettings& settings() const { return settings_; }
  // The threads gather() and prepare() split their work over, idle in between: the frame's
  // systems that run before gather() (the transform update) may use them too.
  jobs::ThreadPool& workers() { return workers_; }
  const jobs::ThreadPool& workers() const { return workers_; }
  // Switches the picture between lit and shadow-only from the next prepare() on.
  void set_view(LightingView view) { settings_.view = view; }
  void set_ambient(const glm::vec3& ambient) { settings_.ambient = ambient; }
  const glm::vec3& ambient() const { return settings_.ambient; }
  // The shadow budgets a running frame may change (the Frame panel's): views redrawn a frame (0:
  // every due view) and the shadow passes' GPU time a frame (0: none), from the next prepare()
  // on. The memory budget sizes the atlas and stays as the renderer was made.
  void set_shadow_budgets(uint32_t view_budget, double time_budget_ms) {
    settings_.shadow_view_budget = view_budget;
    schedule_.set_time_budget(time_budget_ms);
  }
  uint32_t shadow_view_budget() const { return settings_.shadow_view_budget; }
  double shadow_time_budget_ms() const { return schedule_.time_budget().budget_ms(); }
  // From the next prepare() on, each lit frame also records its lights' shadows into `probe`
  // (systems/lighting/shadow_probe.h); null: no more. Deferred lighting only: throws on the
  // fused and every-light paths, which have no per-pixel light lists to walk.
  void probe_shadows(const ShadowProbe* probe);
  // The batched shadow views' raster from the next frame on (ShadowViewBatch::set_raster); no
  // effect on per-light passes.
  void set_shadow_raster(shadows::ShadowRaster raster) {
    if (batch_) batch_->set_raster(raster);
  }
  // What the last prepared frame's shadow passes draw, to hand back with the frame's times.
  struct ShadowWork {
    uint32_t views = 0;        // 2D maps and cube faces drawn
    uint64_t budget_step = 0;  // ShadowTimeBudget::step() it was planned at
    bool steady = true;        // drawn as the frames to come will be (ShadowViewBatch::raster_steady)
  };
  ShadowWork shadow_work() const {
    return {schedule_.stats().views_rendered, schedule_.time_budget_step(),
            !batch_ || batch_->raster_steady()};
  }
  // A timed frame's passes, which drew `work`: what the batch's automatic raster choice
  // (ShadowViewBatch::measured) and the time budget learn from. Returns the frame's shadow passes'
  // milliseconds (shadow_pass_times).
  double measured_shadow_time(const vk::FrameTimings& timings, const ShadowWork& work);
  // The time budget's part of it: the shadow passes of the frame that drew `work` took `ms`. A
  // frame of a raster probe or change says nothing of the frames to come: the budget skips it.
  void measured_shadow_ms(double ms, const ShadowWork& work) {
    if (work.steady) schedule_.measured(work.budget_step, work.views, ms);
  }
  // The shadows' time budget: off (ShadowTimeBudget::on) without one.
  const shadows::ShadowTimeBudget& shadow_time_budget() const { return schedule_.time_budget(); }

  // CPU milliseconds of the last gather() and prepare(), by step: where a CPU frame goes.
  struct CpuSteps {
    double instances = 0.0;  // gather: drawables (GpuScene::gather)
    double lights = 0.0;     // gather: light records and shadow views (gather_lights)
    double schedule = 0.0;   // prepare: caster boxes, tiles, caching
    double upload = 0.0;     // prepare: instance and light buffers of the slot (sorting by light group)
    double views = 0.0;      // prepare: the shadow views' records, casters and batches; lighting pipelines
  };
  const CpuSteps& cpu_steps() const { return cpu_steps_; }

 private:
  vk::VulkanContext& context_;
  uint32_t frames_in_flight_;
  rg::Format frame_format_;
  RendererSettings settings_;
  LightingPath lighting_;
  bool lighting_per_frame_;   // automatic on a CPU device: cpu_lighting_for each frame
  jobs::ThreadPool workers_;  // CPU work of a frame that splits into independent chunks
  GpuScene gpu_scene_;
  GpuTextures textures_;
  ShadowAtlas atlas_;
  shadows::ShadowSchedule schedule_;
  std::optional<ShadowViewBatch> batch_;
  std::optional<ShadowPasses> per_light_;
  // The frame's casters for the schedule: all of them after a new layout, else what moved.
  shadows::CasterUpdate caster_update();
  std::vector<shadows::CasterBounds> casters_;
  std::vector<scene::Aabb> still_changes_;  // where casters that start moving stood
  std::vector<scene::Aabb> moved_casters_;
  CpuSteps cpu_steps_;
  // The passes of the path in use only: a CPU driver compiles a pipeline slowly.
  struct Fused {
    DepthPrepass prepass;
    FusedForwardPass forward;
  };
  struct Deferred {
    GBufferPass gbuffer;
    LightTilesPass light_tiles;
    TiledLightingPass lighting;
  };
  std::optional<ForwardPass> every_light_;
  std::optional<Deferred> deferred_;
  std::optional<Fused> fused_;
  std::optional<TransparentPass> transparent_;  // made with the first transparent surface
  // The format of the image the path lights into: its lit sum, or the frame (fused).
  rg::Format lit_format() const;
  // What the light culling of the frame that last used `slot` reported, read back (both light
  // tiles' passes): returns its dropped (tile, light) pairs and adds its cut tiles to light_tiles_cut_.
  uint64_t read_light_tiles_feedback(uint32_t slot);
  ToneMapPass tone_map_;
  LightRecordUpload light_records_;
  shadows::FrameLights lights_;
  uint64_t dropped_light_pairs_ = 0;
  uint64_t light_tiles_cut_ = 0;
  bool told_of_cut_tiles_ = false;
  uint64_t frames_since_drop_message_ = 300;  // a message at most every 300 frames
  uint32_t contact_shadows_skipped_ = 0;
  bool contact_shadows_message_given_ = false;  // once a run
  uint64_t frames_prepared_ = 0;
};

}  // namespace sg
