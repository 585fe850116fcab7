// SPDX-License-Identifier: MIT
#include "systems/renderer/scene_renderer.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "rendergraph/device/context.h"
#include "systems/gpu/camera.h"
#include "systems/lighting/light_resources.h"
#include "systems/shadow_maps/shadow_pass_times.h"

namespace sg {
namespace {

// Where the shadow images are left: sampled by the lighting.
constexpr rg::ResourceState sampled{rg::PipelineStage::fragment_shader | rg::PipelineStage::compute_shader,
                                    rg::Access::shader_sampled_read, rg::ImageLayout::read_only_optimal};

// Where the shadow maps' static layers are left: written and read by compute (ShadowViewBatch).
constexpr rg::ResourceState static_layers_state{
    rg::PipelineStage::compute_shader, rg::Access::shader_storage_read | rg::Access::shader_storage_write,
    rg::ImageLayout::undefined};

bool batched_shadow_views(const vk::VulkanContext& context, const RendererSettings& settings) {
  return settings.shadow_views == shadows::ShadowViewPath::batched && ShadowViewBatch::supported(context);
}

// Static layers are kept by the compute raster, where it may run.
bool keeps_static_layers(const vk::VulkanContext& context, const RendererSettings& settings) {
  return settings.static_shadow_layers && batched_shadow_views(context, settings) &&
         ShadowViewBatch::may_raster_in_compute(context, settings.shadow_raster);
}

// An optional setting's value, or its default on `context`'s device: `gpu_default` on GPUs, off
// (zero) on CPU devices (RendererSettings::shadow_budget_ms, filtered_lights).
template <typename T>
T or_device_default(const std::optional<T>& setting, const vk::VulkanContext& context, T gpu_default) {
  if (setting) return *setting;
  return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? T{} : gpu_default;
}

// Tiled deferred measured fastest on the H200 (docs/PERFORMANCE.md), and on lavapipe for more
// than a few lights; automatic starts there.
constexpr LightingPath fastest_lighting = LightingPath::deferred;

// Milliseconds since `mark`, which moves to now.
double lap(std::chrono::steady_clock::time_point& mark) {
  const auto now = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::milli>(now - std::exchange(mark, now)).count();
}

}  // namespace

SceneRenderer::SceneRenderer(vk::VulkanContext& context, const scene::Scene& scene, uint32_t frames_in_flight,
                             rg::Format frame_format, const RendererSettings& settings)
    : context_(context),
      frames_in_flight_(frames_in_flight),
      frame_format_(frame_format),
      settings_(settings),
      lighting_(settings.lighting == LightingPath::automatic ? fastest_lighting : settings.lighting),
      lighting_per_frame_(settings.lighting == LightingPath::automatic &&
                          context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU),
      workers_(settings.cpu_threads == 0 ? jobs::ThreadPool::default_workers() : settings.cpu_threads - 1),
      gpu_scene_(context, scene.meshes, frames_in_flight),
      textures_(context, scene.textures),
      atlas_(context, uint64_t{settings.shadow_memory_mib} << 20, keeps_static_layers(context, settings)),
      schedule_({atlas_.shape().page_size, atlas_.shape().max_pages, shadows::min_shadow_resolution},
                atlas_.static_layers() != nullptr, settings.shadow_resolution,
                or_device_default(settings.shadow_budget_ms, context, default_gpu_shadow_budget_ms),
                settings.shadow_time_policy),
      tone_map_(context, frame_format),
      light_records_(context, frames_in_flight) {
  if (!shadow_comparisons_filtered()) {
    std::printf(
        "shadowgraph: %s cannot filter the shadow maps' depth format, so each tap of the 2D pcf, noise and "
        "pcss kernels compares the nearest texel instead of a bilinear 2x2: their edges are harder than on "
        "devices that filter it\n",
        context.properties().deviceName);
  }
  if (batched_shadow_views(context, settings)) {
    batch_.emplace(context, frames_in_flight, textures_, settings.shadow_raster,
                   atlas_.static_layers() != nullptr);
  } else {
    per_light_.emplace(context, frames_in_flight, textures_);
  }
  switch (lighting_) {
    case LightingPath::every_light: every_light_.emplace(context, frames_in_flight, textures_); break;
    case LightingPath::fused:
      fused_.emplace(
          Fused{DepthPrepass(context, textures_), FusedForwardPass(context, textures_, frame_format)});
      break;
    case LightingPath::automatic:  // resolved above
    case LightingPath::deferred: {
      TiledLightingPass lighting(
          context, settings.lit_sum_start,
          or_device_default(settings.filtered_lights, context, default_gpu_filtered_lights),
          settings.light_records);
      if (lighting.filtered_lights() > 0) {
        std::printf(
            "shadowgraph: at each pixel the %u lights adding most to it run their shadow filters, the others "
            "the hard test (--filtered-shadows; 0: all filter)\n",
            lighting.filtered_lights());
      }
      const bool lit_sum_from_gbuffer = lighting.lit_sum_from_gbuffer();
      deferred_.emplace(Deferred{GBufferPass(context, frames_in_flight, textures_, lit_sum_from_gbuffer),
                                 LightTilesPass(context, frames_in_flight), std::move(lighting)});
      break;
    }
  }
  if (lighting_per_frame_)
    fused_.emplace(
        Fused{DepthPrepass(context, textures_), FusedForwardPass(context, textures_, frame_format)});
}

void SceneRenderer::gather(const ecs::World& world) {
  auto mark = std::chrono::steady_clock::now();
  workers_.wake();  // they wake while the instances are put in order, which is serial
  gpu_scene_.gather(world, &workers_);
  cpu_steps_.instances = lap(mark);
  shadows::gather_lights(world, gpu_scene_.bounds(), settings_.lights, lights_, &workers_);
  cpu_steps_.lights = lap(mark);
}

void SceneRenderer::prepare(uint32_t slot, const scene::CameraPose& pose, const scene::Camera& lens,
                            uint32_t width, uint32_t height) {
  auto mark = std::chrono::steady_clock::now();
  workers_.wake();  // the schedule's batches come soon: threads wake while the casters are listed
  if (!settings_.cache_shadows) schedule_.invalidate_all();
  // A new layout makes every moving instance still (GpuScene::moving): layers drawn without them
  // miss them now.
  if (gpu_scene_.laid_out_in_last_gather()) schedule_.forget_static_layers();
  if (batch_ && !batch_->all_casters_kept(slot)) {
    std::printf(
        "shadowgraph: shadow views kept more casters than fit; the buffer grows and every map is redrawn\n");
    schedule_.invalidate_all();
  }
  const shadows::CasterUpdate casters = caster_update();
  const float aspect = float(width) / float(std::max(height, 1u));
  const shadows::ShadowCamera camera{pose.eye, projection_matrix(lens, aspect) * view_matrix(pose),
                                     float(height) / lens.yfov};
  shadows::place_cascades(lights_, shadows::cascade_camera(pose, lens, aspect), gpu_scene_.bounds());
  schedule_.schedule(lights_, camera, casters, settings_.shadow_view_budget, &workers_);
  if (atlas_.fit(schedule_.pages_used())) {
    // A new image holds nothing: every map is drawn again, this frame.
    schedule_.invalidate_all();
    schedule_.schedule(lights_, camera, casters, settings_.shadow_view_budget, &workers_);
  }
  for (const std::optional<std::string>& message :
       {schedule_.take_budget_message(), schedule_.take_time_budget_message()}) {
    if (message) std::printf("shadowgraph: %s\n", message->c_str());
  }
  cpu_steps_.schedule = lap(mark);

  gpu_scene_.upload(slot, &workers_);
  const vk::Buffer& records = light_records_.upload(lights_, slot, &workers_);
  cpu_steps_.upload = lap(mark);
  const uint32_t page_size = atlas_.shape().page_size;
  if (batch_) {
    batch_->prepare(slot, lights_, gpu_scene_, page_size, &workers_);
    if (!batch_->static_layers_kept()) schedule_.static_layers_not_kept();
  }
  if (per_light_) {
    per_light_->prepare(slot, lights_, gpu_scene_, page_size, settings_.cube_shadows, settings_.cull_casters);
  }
  if (lighting_per_frame_) {
    lighting_ = cpu_lighting_for(static_cast<uint32_t>(lights_.records.size()), lights_.contact_lights(),
                                 gpu_scene_.triangles());
  }
  // Only deferred lighting reads the depth buffer its contact shadows march through.
  contact_shadows_skipped_ = lighting_ == LightingPath::deferred ? 0 : lights_.contact_lights();
  if (contact_shadows_skipped_ > 0 && !contact_shadows_message_given_) {
    std::printf(
        "shadowgraph: %u lights have contact shadows, which %s lighting does not draw (deferred does)\n",
        contact_shadows_skipped_, std::string(to_string(lighting_)).c_str());
    contact_shadows_message_given_ = true;
  }
  // What the frame that last used this slot could not list, now that its fence has passed, and
  // how its tiles' light groups fell (TiledLightingPass's group sets).
  dropped_light_pairs_ = read_light_tiles_feedback(slot);
  if (dropped_light_pairs_ > 0 && frames_since_drop_message_ >= 300) {
    std::printf(
        "shadowgraph: %llu (tile, light) pairs found no room in the light lists' pool, which grows for the "
        "frames after; those lights are missing there in this frame\n",
        static_cast<unsigned long long>(dropped_light_pairs_));
    frames_since_drop_message_ = 0;
  }
  ++frames_since_drop_message_;
  if (light_tiles_cut_ > 0 && !told_of_cut_tiles_) {
    std::printf(
        "shadowgraph: the CPU driver ended the light culling's loops early (llvmpipe ends a shader "
        "invocation's loops after 65,535 iterations in all): some tiles' lists miss lights of the %zu; fewer "
        "lights, or a GPU, list them all (--stats' light_tiles_cut counts the tiles)\n",
        lights_.records.size());
    told_of_cut_tiles_ = true;
  }
  switch (lighting_) {
    case LightingPath::every_light:
      every_light_->prepare(slot, gpu_scene_, records, atlas_, settings_.view);
      break;
    case LightingPath::fused:
      fused_->prepass.prepare(gpu_scene_);
      fused_->forward.prepare(shadows::groups_present(lights_.group_begin, lights_.group_types),
                              settings_.view, gpu_scene_);
      break;
    case LightingPath::automatic:  // resolved
    case LightingPath::deferred:
      deferred_->gbuffer.prepare(slot, gpu_scene_);
      deferred_->lighting.prepare(lights_, settings_.view, settings_.group_sets,
                                  deferred_->light_tiles.tiles_by_groups(), settings_.pipeline_builds);
      break;
  }
  if (gpu_scene_.has_transparent()) {
    if (!transparent_) transparent_.emplace(context_, frames_in_flight_, textures_);
    gpu_scene_.order_transparent(pose.eye);
    // Lit as the opaque surfaces were: from tile lists, or by every light.
    const bool tiled = lighting_ == LightingPath::deferred;
    transparent_->prepare(lit_format(), tiled,
                          shadows::groups_present(lights_.group_begin, lights_.group_types), settings_.view,
                          gpu_scene_, slot, camera.view_projection, {width, height});
  }
  ++frames_prepared_;
  cpu_steps_.views = lap(mark);
}

shadows::CasterUpdate SceneRenderer::caster_update() {
  // After the instances were ordered anew, the schedule compares every caster with the frame
  // before; otherwise GpuScene knows which moved, and from where.
  if (gpu_scene_.laid_out_in_last_gather()) {
    casters_.clear();
    const std::span<const scene::Aabb> bounds = gpu_scene_.instance_bounds();
    const std::span<const uint64_t> keys = gpu_scene_.instance_keys();
    for (const VkDrawIndexedIndirectCommand& group : gpu_scene_.caster_groups()) {
      for (uint32_t i = group.firstInstance; i < group.firstInstance + group.instanceCount; ++i) {
        casters_.push_back({keys[i], bounds[i], gpu_scene_.shadow_layers(i)});
      }
    }
    return shadows::CasterUpdate(casters_);
  }
  // A caster that starts moving leaves the static layers where it stood; after that its boxes
  // concern only the moving casters drawn over them.
  still_changes_.clear();
  moved_casters_.clear();
  const std::span<const uint32_t> replaced = gpu_scene_.replaced();
  const std::span<const scene::Aabb> before = gpu_scene_.replaced_bounds_before();
  const std::span<const scene::Aabb> after = gpu_scene_.replaced_bounds_after();
  for (size_t k = 0; k < replaced.size(); ++k) {
    const uint32_t i = replaced[k];
    const scene::Aabb& now = after[k];
    if (!gpu_scene_.casts_shadow(i) || (now.min == before[k].min && now.max == before[k].max)) continue;
    if (!before[k].empty())
      (gpu_scene_.first_moved_in_last_gather(i) ? still_changes_ : moved_casters_).push_back(before[k]);
    if (!now.empty()) moved_casters_.push_back(now);
  }
  return shadows::CasterUpdate::changes(still_changes_, moved_casters_);
}

void SceneRenderer::probe_shadows(const ShadowProbe* probe) {
  if (!deferred_) throw std::logic_error("SceneRenderer::probe_shadows: the lighting path is not deferred");
  deferred_->lighting.probe_shadows(probe);
}

RenderedFrame SceneRenderer::add_passes(rg::RenderGraph& graph, vk::GraphImports& imports,
                                        rg::ImageHandle frame, uint32_t slot, const scene::CameraPose& pose,
                                        const scene::Camera& lens) {
  rg::ImageHandle atlas = imports.import_image(graph, "shadow atlas", atlas_.image(), sampled);
  if (batch_) {
    const vk::Buffer* layers = atlas_.static_layers();
    const rg::BufferHandle static_layers =
        layers ? imports.import_buffer(graph, "shadow static layers", *layers, static_layers_state)
               : rg::BufferHandle{};
    atlas = batch_->add_to(graph, atlas, static_layers, gpu_scene_, slot);
  } else {
    atlas = per_light_->add_to(graph, atlas, lights_, gpu_scene_, slot, settings_.cube_shadows);
  }

  const rg::ImageDesc& target = graph.resources()[frame.index].image;
  const glm::mat4 view_projection =
      projection_matrix(lens, float(target.width) / float(target.height)) * view_matrix(pose);
  const auto light_count = static_cast<uint32_t>(lights_.records.size());
  const LightTileGrid grid = LightTileGrid::of(target.width, target.height);
  const glm::vec3 ambient_term = settings_.view == LightingView::lit ? settings_.ambient : glm::vec3(0.0f);
  const FrameConstants constants{view_projection, glm::vec4(pose.eye, 0.0f),
                                 glm::uvec4(light_count, grid.across, 0, 0), glm::vec4(ambient_term, 0.0f)};
  const vk::Buffer& records = light_records_.buffer(slot);

  if (lighting_ == LightingPath::fused) {  // lights and tone-maps in one pass, straight into the frame
    const rg::ImageHandle prepass =
        fused_->prepass.add_to(graph, target.width, target.height, gpu_scene_, slot, constants);
    FusedTargets fused = fused_->forward.add_to(graph, prepass, frame, atlas, records, gpu_scene_, slot,
                                                constants, settings_.exposure);
    if (gpu_scene_.has_transparent()) {
      fused.frame = transparent_->add_to(graph, fused.frame, fused.depth, atlas, records, light_count,
                                         gpu_scene_, slot, tone_mapping(constants, settings_.exposure));
    }
    return {fused.frame, fused.depth, atlas, std::nullopt};
  }
  rg::ImageHandle lit_sum;
  rg::ImageHandle depth;
  std::optional<LightTiles> light_tiles;
  if (lighting_ == LightingPath::every_light) {
    const ForwardTargets lit =
        every_light_->add_to(graph, target.width, target.height, atlas, gpu_scene_, slot, constants);
    lit_sum = lit.lit_sum;
    depth = lit.depth;
  } else {
    const GBuffer gbuffer =
        deferred_->gbuffer.add_to(graph, target.width, target.height, gpu_scene_, slot, constants);
    const LightTiles tiles =
        deferred_->light_tiles.add_to(graph, slot, gbuffer.depth, records, light_count, view_projection,
                                      nullptr, nullptr, deferred_->lighting.group_sets());
    lit_sum = deferred_->lighting.add_to(graph, gbuffer, tiles, atlas, records, view_projection, pose.eye,
                                         ambient_term);
    depth = gbuffer.depth;
    light_tiles = tiles;
  }
  if (gpu_scene_.has_transparent()) {
    lit_sum =
        transparent_->add_to(graph, lit_sum, depth, atlas, records, light_count, gpu_scene_, slot, constants);
  }
  return {tone_map_.add_to(graph, lit_sum, frame, settings_.exposure), depth, atlas, light_tiles};
}

uint64_t SceneRenderer::read_light_tiles_feedback(uint32_t slot) {
  const uint64_t dropped = (deferred_ ? deferred_->light_tiles.take_dropped_pairs(slot) : 0) +
                           (transparent_ ? transparent_->take_dropped_pairs(slot) : 0);
  light_tiles_cut_ +=
      (deferred_ ? deferred_->light_tiles.tiles_cut() : 0) + (transparent_ ? transparent_->tiles_cut() : 0);
  return dropped;
}

std::optional<uint64_t> SceneRenderer::light_list_pairs() const {
  if (!deferred_ || frames_prepared_ <= frames_in_flight_) return std::nullopt;
  return deferred_->light_tiles.listed_pairs();
}

uint64_t SceneRenderer::drain_dropped_light_pairs() {
  uint64_t dropped = 0;
  for (uint32_t slot = 0; slot < frames_in_flight_; ++slot) dropped += read_light_tiles_feedback(slot);
  return dropped;
}

rg::Format SceneRenderer::lit_format() const {
  switch (lighting_) {
    case LightingPath::fused: return frame_format_;
    case LightingPath::every_light: return ForwardPass::lit_sum_format;
    case LightingPath::automatic:  // resolved
    case LightingPath::deferred: break;
  }
  return TiledLightingPass::lit_sum_format;
}

double SceneRenderer::measured_shadow_time(const vk::FrameTimings& timings, const ShadowWork& work) {
  const ShadowPassTimes times = shadow_pass_times(timings);
  if (batch_) batch_->measured(times, work.views);
  measured_shadow_ms(times.ms, work);
  return times.ms;
}

uint64_t SceneRenderer::shadow_caster_draws() const {
  return batch_ ? batch_->kept_pairs() : per_light_->kept_casters();
}

}  // namespace sg
