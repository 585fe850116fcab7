// SPDX-License-Identifier: MIT
#include "systems/frame/frame.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "ecs/transform_system.h"
#include "rendergraph/device/context.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "systems/scene/node_animation.h"

namespace sg {
namespace {

constexpr rg::ResourceState transfer_source{rg::PipelineStage::all_transfer, rg::Access::transfer_read,
                                            rg::ImageLayout::transfer_src_optimal};

// A pass blitting the whole of `source` onto the whole of `target`, filtered where the sizes
// differ; returns `target`'s new version.
rg::ImageHandle add_blit(rg::RenderGraph& graph, const char* name, rg::ImageHandle source,
                         rg::ImageHandle target) {
  graph.add_pass(
      name,
      [&](rg::PassBuilder& b) {
        b.read(source, rg::Usage::transfer);
        target = b.write(target, rg::Usage::transfer);
      },
      [source, target, &graph](const vk::PassRecorder& rec) {
        const rg::ImageDesc& src = graph.resources()[source.index].image;
        const rg::ImageDesc& dst = graph.resources()[target.index].image;
        VkImageBlit region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.srcOffsets[1] = {int32_t(src.width), int32_t(src.height), 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.dstOffsets[1] = {int32_t(dst.width), int32_t(dst.height), 1};
        vkCmdBlitImage(rec.cmd(), rec.image(source), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, rec.image(target),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_LINEAR);
      });
  return target;
}

// Blits the frame onto the swapchain image (scaling if sizes differ) and leaves it presentable.
void add_present(rg::RenderGraph& graph, vk::GraphImports& imports, rg::ImageHandle frame,
                 const PresentTarget& target) {
  // The first use chains with the acquire semaphore's wait at acquire_wait_stage; the contents
  // of an acquired image are not needed (UNDEFINED).
  const rg::ImageHandle swapchain = imports.import_image(
      graph, "swapchain", target.image, target.format, target.extent,
      rg::ResourceState{rg::PipelineStage::all_transfer, rg::Access::none, rg::ImageLayout::undefined},
      rg::ResourceState{rg::PipelineStage::none, rg::Access::none, rg::ImageLayout::present_src});
  add_blit(graph, "present", frame, swapchain);
}

}  // namespace

Frame::Frame(vk::VulkanContext& context, SceneView& view, const FrameSettings& settings,
             uint32_t frames_in_flight, std::vector<FrameExtension> extensions)
    : context_(context),
      view_(view),
      extensions_(std::move(extensions)),
      playing_(settings.animate),
      renderer_(context, view.scene, frames_in_flight, frame_format, settings.effective_renderer()),
      executor_(context, frames_in_flight) {}

uint64_t Frame::take_dropped_light_pairs() {
  return std::exchange(dropped_light_pairs_, 0) + renderer_.drain_dropped_light_pairs();
}

void Frame::resize(VkExtent2D extent, float render_scale) {
  if (!(render_scale > 0.0f && render_scale <= 1.0f)) {
    throw std::invalid_argument("Frame::resize: the render scale must be in (0, 1], got " +
                                std::to_string(render_scale));
  }
  const auto color_image = [this](VkExtent2D size, const char* name) {
    return vk::Image(context_, {size, vk::to_vk(frame_format),
                                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                1, 1, VK_IMAGE_VIEW_TYPE_2D, name});
  };
  const auto scaled = [render_scale](uint32_t size) {
    return std::max(1u, static_cast<uint32_t>(std::lround(double(size) * render_scale)));
  };
  image_ = color_image(extent, "frame");
  scene_extent_ = {scaled(extent.width), scaled(extent.height)};
  scene_image_.reset();
  if (scene_extent_.width != extent.width || scene_extent_.height != extent.height) {
    scene_image_ = color_image(scene_extent_, "scene color");
  }
}

vk::FrameSlot& Frame::begin(vk::FrameRing& ring) {
  // Woken workers wait for a batch this long before they sleep again: half of it leaves room
  // for a wait that ends later than the last one did.
  return ring.begin_frame([this] { renderer_.workers().wake(); }, jobs::ThreadPool::spin_time / 2);
}

void Frame::record(const vk::FrameSlot& frame, double time_seconds,
                   const std::optional<PresentTarget>& present) {
  auto mark = std::chrono::steady_clock::now();
  const auto timed = [&](std::vector<double>& samples) {
    const auto now = std::chrono::steady_clock::now();
    samples.push_back(std::chrono::duration<double, std::milli>(now - mark).count());
    mark = now;
  };
  const double seconds = time_seconds - last_time_seconds_;  // since the last frame
  last_time_seconds_ = time_seconds;
  for (const FrameExtension& extension : extensions_) {
    if (extension.update) extension.update(seconds);
  }
  update(seconds);
  timed(phase_ms_.update);
  renderer_.gather(std::as_const(view_.scene.world));
  timed(phase_ms_.gather);
  report_shadow_time();
  renderer_.prepare(frame.slot, view_.pose, view_.lens, scene_extent_.width, scene_extent_.height);
  for (const FrameExtension& extension : extensions_) {
    if (extension.prepare) extension.prepare(frame.slot);
  }
  timed(phase_ms_.prepare);
  const SceneRenderer::CpuSteps& steps = renderer_.cpu_steps();
  phase_ms_.instances.push_back(steps.instances);
  phase_ms_.lights.push_back(steps.lights);
  phase_ms_.schedule.push_back(steps.schedule);
  phase_ms_.upload.push_back(steps.upload);
  phase_ms_.views.push_back(steps.views);
  for (size_t step = 0; step < shadows::schedule_step_count; ++step) {
    phase_ms_.schedule_steps[step].push_back(renderer_.schedule_step_times()[step]);
  }
  const shadows::ShadowScheduleStats& shadows = renderer_.shadow_stats();
  shadow_views_rendered_.push_back(shadows.views_rendered);
  shadow_views_cached_.push_back(shadows.views_cached);
  shadow_views_moving_only_.push_back(shadows.views_moving_only);
  map_timeline_.lag_p50.push_back(shadows.map_lag_p50);
  map_timeline_.lag_p99.push_back(shadows.map_lag_p99);
  map_timeline_.lag_max.push_back(shadows.map_lag_max);
  map_timeline_.lights_changed_tier.push_back(shadows.lights_changed_tier);
  map_timeline_.lights_retiled.push_back(shadows.lights_retiled);
  map_timeline_.atlas_repacks += shadows.atlas_repacked ? 1 : 0;
  if (!first_maps_ && shadows.lights_waiting == 0) first_maps_ = frame.frame_number;
  drawn_views_[frame.frame_number % drawn_views_.size()] = {frame.frame_number, renderer_.shadow_work()};
  record_shadow_budgets(shadows);
  dropped_light_pairs_ += renderer_.dropped_light_pairs();
  if (const std::optional<uint64_t> pairs = renderer_.light_list_pairs())
    light_list_pairs_.push_back(double(*pairs));
  declare_passes(frame.slot, present);
  timed(phase_ms_.declare);
  execute(frame);
  timed(phase_ms_.execute);
}

void Frame::report_shadow_time() {
  const std::optional<vk::FrameTimings>& timings = executor_.latest_timings();
  if (!timings || timings->frame_number == reported_frame_) return;
  reported_frame_ = timings->frame_number;
  const DrawnViews& drawn = drawn_views_[timings->frame_number % drawn_views_.size()];
  if (drawn.frame != timings->frame_number) return;
  shadow_budget_.shadow_ms.push_back(renderer_.measured_shadow_time(*timings, drawn.work));
}

void Frame::record_shadow_budgets(const shadows::ShadowScheduleStats& shadows) {
  ShadowBudgetRecord& record = shadow_budget_;
  record.lights_demoted_by_time.push_back(shadows.lights_demoted_by_time);
  record.views_deferred_by_time.push_back(shadows.views_deferred_by_time);
  record.lights_demoted_by_memory.push_back(shadows.lights_demoted_by_memory);
  record.lights_dropped_by_memory.push_back(shadows.lights_dropped_by_memory);
  if (shadows.lights_demoted_by_time > 0 || shadows.views_deferred_by_time > 0) ++record.frames_bound_by_time;
  if (shadows.lights_demoted_by_memory > 0 || shadows.lights_dropped_by_memory > 0)
    ++record.frames_bound_by_memory;
}

double Frame::last_cpu_ms() const {
  const auto last = [](const std::vector<double>& samples) { return samples.empty() ? 0.0 : samples.back(); };
  return last(phase_ms_.update) + last(phase_ms_.gather) + last(phase_ms_.prepare) + last(phase_ms_.declare) +
         last(phase_ms_.execute);
}

vk::DepthImage Frame::read_captured_depth() const {
  if (!depth_capture_) throw std::logic_error("Frame::read_captured_depth: capture_depth() was not called");
  return depth_capture_->read(context_);
}

void Frame::update(double seconds) {
  ecs::World& world = view_.scene.world;
  // Paused, nothing is written, so cached shadow maps stay valid.
  if (playing_) {
    animation_seconds_ += seconds;
    const auto time = static_cast<float>(animation_seconds_);
    scene::animate_orbits(world, time, &renderer_.workers());
    scene::animate_bobs(world, time, &renderer_.workers());
    scene::animate_nodes(world, time);
  }
  ecs::update_world_transforms(world, transforms_updated_, &renderer_.workers());
  transforms_updated_ = world.tick();
  world.advance_tick();
}

void Frame::declare_passes(uint32_t slot, const std::optional<PresentTarget>& present) {
  graph_ = rg::RenderGraph();
  const rg::ImageHandle frame_image = imports_.import_image(graph_, "frame", image_, transfer_source);
  const rg::ImageHandle scene_image =
      scene_image_ ? imports_.import_image(graph_, "scene color", *scene_image_, transfer_source)
                   : frame_image;
  const RenderedFrame targets =
      renderer_.add_passes(graph_, imports_, scene_image, slot, view_.pose, view_.lens);
  if (depth_capture_) depth_capture_->add_to(context_, graph_, imports_, targets.depth);
  // The renderer's smaller picture scaled up into the frame (resize's render scale).
  rg::ImageHandle color =
      scene_image_ ? add_blit(graph_, upscale_pass_name, targets.color, frame_image) : targets.color;
  for (const FrameExtension& extension : extensions_) {
    if (extension.add_passes) color = extension.add_passes(graph_, targets, color, slot);
  }
  if (present) add_present(graph_, imports_, color, *present);
}

void Frame::execute(const vk::FrameSlot& frame) {
  rg::CompileResult compiled = plans_.get_or_compile(graph_);
  if (!compiled.ok()) {
    throw std::logic_error("the frame graph does not compile: " + compiled.errors.front().message);
  }
  plan_ = compiled.plan;
  executor_.execute(frame.cmd, frame.slot, frame.frame_number, graph_, plan_, imports_.resources());
  imports_.remember(*plan_);
}

}  // namespace sg
