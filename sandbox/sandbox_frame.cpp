#include "sandbox/sandbox_frame.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>

#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "rendergraph/device/context.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "sandbox/scene_sidecar.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/node_animation.h"
#include "systems/scene/shadow_settings.h"

namespace sg::sandbox {
namespace {

constexpr rg::ResourceState transfer_source{rg::PipelineStage::all_transfer, rg::Access::transfer_read,
                                            rg::ImageLayout::transfer_src_optimal};

// Blits the frame onto the swapchain image (scaling if sizes differ) and leaves it presentable.
void add_present(rg::RenderGraph& graph, vk::GraphImports& imports, rg::ImageHandle frame,
                 const PresentTarget& target) {
  // The first use chains with the acquire semaphore's wait at acquire_wait_stage; the contents
  // of an acquired image are not needed (UNDEFINED).
  rg::ImageHandle swapchain = imports.import_image(
      graph, "swapchain", target.image, target.format, target.extent,
      rg::ResourceState{rg::PipelineStage::all_transfer, rg::Access::none, rg::ImageLayout::undefined},
      rg::ResourceState{rg::PipelineStage::none, rg::Access::none, rg::ImageLayout::present_src});
  graph.add_pass(
      "present",
      [&](rg::PassBuilder& b) {
        b.read(frame, rg::Usage::transfer);
        swapchain = b.write(swapchain, rg::Usage::transfer);
      },
      [frame, swapchain, &graph](const vk::PassRecorder& rec) {
        const rg::ImageDesc& src = graph.resources()[frame.index].image;
        const rg::ImageDesc& dst = graph.resources()[swapchain.index].image;
        VkImageBlit region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.srcOffsets[1] = {int32_t(src.width), int32_t(src.height), 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.dstOffsets[1] = {int32_t(dst.width), int32_t(dst.height), 1};
        vkCmdBlitImage(rec.cmd(), rec.image(frame), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       rec.image(swapchain), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region,
                       VK_FILTER_LINEAR);
      });
}

}  // namespace

RendererSettings renderer_settings(const Options& options) {
  RendererSettings settings;
  settings.lights.shadows = options.shadows;
  settings.cube_shadows = options.cube_shadows;
  settings.lighting = options.lighting;
  settings.lit_sum_start = options.lit_sum_start;
  settings.exposure = options.exposure;
  settings.view = options.view;
  settings.shadow_views = options.shadow_views;
  settings.shadow_raster = options.shadow_raster;
  settings.shadow_resolution = options.shadow_resolution;
  settings.shadow_memory_bytes = uint64_t{options.shadow_memory_mib} << 20;
  settings.shadow_view_budget = options.shadow_updates;
  settings.cache_shadows = options.shadow_cache;
  settings.static_shadow_layers = options.shadow_layers;
  settings.cpu_threads = options.threads;
  if (options.naive) {
    settings.shadow_views = shadows::ShadowViewPath::per_light;
    settings.cache_shadows = false;
    settings.shadow_view_budget = 0;
    settings.cube_shadows = shadows::CubeShadowMode::six_passes;
    settings.cull_casters = false;
    settings.lighting = LightingPath::every_light;
  }
  return settings;
}

SandboxFrame::SandboxFrame(vk::VulkanContext& context, SandboxScene& scene, const Options& options,
                           uint32_t frames_in_flight, GLFWwindow* window)
    : context_(context),
      scene_(scene),
      depth_overlay_enabled_(options.depth_overlay),
      animate_(options.animate),
      scene_name_(options.scene),
      renderer_(context, scene.scene, frames_in_flight, frame_format, renderer_settings(options)),
      depth_overlay_(context, frame_format),
      executor_(context, frames_in_flight) {
  // The panels switch the heat map on and off, so with them it is always ready.
  const bool panels = options.ui.value_or(window != nullptr);
  if (options.light_heatmap || panels) light_heatmap_.emplace(context, frame_format);
  if (panels) {
    ui_ = std::make_unique<SandboxUi>(window);
    ui_->set_playing(options.animate);
    ui_->set_view(options.view);
    ui_->set_light_heatmap(options.light_heatmap);
    ui_pass_ = std::make_unique<UiPass>(context, frame_format, frames_in_flight);
  }
  // --algorithm sets every light's algorithm once, here: the panels and scripts may change it
  // afterwards, and a per-frame override would undo their edits.
  if (options.algorithm) {
    scene.scene.world.query<scene::ShadowSettings>().for_each(
        [&](scene::ShadowSettings& shadow) { shadow.algorithm = *options.algorithm; });
  }
}

SandboxFrame::~SandboxFrame() = default;

uint64_t SandboxFrame::take_dropped_light_pairs() {
  return std::exchange(dropped_light_pairs_, 0) + renderer_.drain_dropped_light_pairs();
}

bool SandboxFrame::ui_wants_input() const { return ui_ && ui_->wants_input(); }

void SandboxFrame::resize(VkExtent2D extent) {
  image_ = vk::Image(context_, {extent, vk::to_vk(frame_format),
                                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, 1, 1,
                                VK_IMAGE_VIEW_TYPE_2D, "frame"});
}

vk::FrameSlot& SandboxFrame::begin(vk::FrameRing& ring) {
  // Woken workers wait for a batch this long before they sleep again: half of it leaves room
  // for a wait that ends later than the last one did.
  return ring.begin_frame([this] { renderer_.workers().wake(); }, ecs::ThreadPool::spin_time / 2);
}

void SandboxFrame::record(const vk::FrameSlot& frame, double time_seconds,
                          const std::optional<PresentTarget>& present) {
  auto mark = std::chrono::steady_clock::now();
  const auto timed = [&](std::vector<double>& samples) {
    const auto now = std::chrono::steady_clock::now();
    samples.push_back(std::chrono::duration<double, std::milli>(now - mark).count());
    mark = now;
  };
  const double seconds = time_seconds - last_time_seconds_;  // since the last frame
  last_time_seconds_ = time_seconds;
  const ImDrawData* panels = nullptr;
  if (ui_)
    panels = ui_->build(scene_.scene, scene_.pose, ui_facts(), image_.extent(), static_cast<float>(seconds));
  if (ui_ && ui_->take_save_request()) save_edits();
  if (ui_) renderer_.set_view(ui_->view());
  update(seconds);
  timed(phase_ms_.update);
  renderer_.gather(std::as_const(scene_.scene.world));
  timed(phase_ms_.gather);
  renderer_.prepare(frame.slot, scene_.pose, scene_.lens, image_.extent().width, image_.extent().height);
  if (ui_pass_) ui_pass_->prepare(frame.slot, panels, ui_->depth_views());
  timed(phase_ms_.prepare);
  const SceneRenderer::CpuSteps& steps = renderer_.cpu_steps();
  phase_ms_.instances.push_back(steps.instances);
  phase_ms_.lights.push_back(steps.lights);
  phase_ms_.schedule.push_back(steps.schedule);
  phase_ms_.upload.push_back(steps.upload);
  phase_ms_.views.push_back(steps.views);
  const shadows::ShadowScheduleStats& shadows = renderer_.shadow_stats();
  shadow_views_rendered_.push_back(shadows.views_rendered);
  shadow_views_cached_.push_back(shadows.views_cached);
  shadow_views_moving_only_.push_back(shadows.views_moving_only);
  dropped_light_pairs_ += renderer_.dropped_light_pairs();
  declare_passes(frame.slot, present);
  timed(phase_ms_.declare);
  execute(frame);
  timed(phase_ms_.execute);
}

void SandboxFrame::set_view(LightingView view) {
  renderer_.set_view(view);
  if (ui_) ui_->set_view(view);
}

void SandboxFrame::save_edits() const {
  const std::filesystem::path path = sidecar_path(scene_name_);
  save_sidecar(path, scene_.scene, scene_.pose);
  std::printf("shadowgraph: saved the lights and camera to %s\n", path.string().c_str());
}

vk::DepthImage SandboxFrame::read_captured_depth() const {
  if (!depth_capture_)
    throw std::logic_error("SandboxFrame::read_captured_depth: capture_depth() was not called");
  return depth_capture_->read(context_);
}

UiFacts SandboxFrame::ui_facts() const {
  UiFacts facts;
  const auto last = [](const std::vector<double>& samples) { return samples.empty() ? 0.0 : samples.back(); };
  facts.cpu_frame_ms = last(phase_ms_.update) + last(phase_ms_.gather) + last(phase_ms_.prepare) +
                       last(phase_ms_.declare) + last(phase_ms_.execute);
  if (const std::optional<vk::FrameTimings>& timings = executor_.latest_timings()) {
    for (size_t p = 0; p < timings->pass_ms.size(); ++p) {
      facts.gpu_frame_ms += timings->pass_ms[p];
      facts.passes.emplace_back(timings->plan->passes[p].name, timings->pass_ms[p]);
    }
  }
  const shadows::ShadowScheduleStats& shadows = renderer_.shadow_stats();
  facts.views_rendered = shadows.views_rendered;
  facts.views_cached = shadows.views_cached;
  facts.views_moving_only = shadows.views_moving_only;
  facts.lights_without_shadow = shadows.lights_without_shadow;
  facts.lights = static_cast<uint32_t>(renderer_.lights().records.size());
  facts.shadow_mib = double(renderer_.shadow_atlas().bytes()) / (1 << 20);
  facts.lighting = lighting_path_name(renderer_.lighting());
  facts.frame_lights = &renderer_.lights();
  facts.atlas_page = renderer_.shadow_atlas().shape().page_size;
  facts.atlas_pages = renderer_.shadow_atlas().pages();
  if (context_.validation_enabled()) facts.validation_errors = context_.validation_errors();
  return facts;
}

void SandboxFrame::update(double seconds) {
  ecs::World& world = scene_.scene.world;
  // Paused, nothing is written, so cached shadow maps stay valid.
  if (ui_ ? ui_->playing() : animate_) {
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

void SandboxFrame::declare_passes(uint32_t slot, const std::optional<PresentTarget>& present) {
  graph_ = rg::RenderGraph();
  const rg::ImageHandle frame_image = imports_.import_image(graph_, "frame", image_, transfer_source);
  const RenderedFrame targets =
      renderer_.add_passes(graph_, imports_, frame_image, slot, scene_.pose, scene_.lens);
  if (depth_capture_) depth_capture_->add_to(context_, graph_, imports_, targets.depth);
  rg::ImageHandle color = targets.color;
  if (depth_overlay_enabled_) color = depth_overlay_.add_to(graph_, targets.depth, color, scene_.lens);
  const bool heatmap = ui_ ? ui_->light_heatmap() : light_heatmap_.has_value();
  if (heatmap && targets.light_tiles) color = light_heatmap_->add_to(graph_, *targets.light_tiles, color);
  if (ui_pass_) color = ui_pass_->add_to(graph_, color, targets.shadow_atlas, slot);
  if (present) add_present(graph_, imports_, color, *present);
}

void SandboxFrame::execute(const vk::FrameSlot& frame) {
  rg::CompileResult compiled = plans_.get_or_compile(graph_);
  if (!compiled.ok()) {
    throw std::logic_error("the sandbox's frame graph does not compile: " + compiled.errors.front().message);
  }
  plan_ = compiled.plan;
  executor_.execute(frame.cmd, frame.slot, frame.frame_number, graph_, plan_, imports_.resources());
  imports_.remember(*plan_);
}

}  // namespace sg::sandbox
