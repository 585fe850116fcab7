#include "systems/scene_renderer.h"

#include <span>

#include "systems/camera.h"

namespace sg {
namespace {

// Where the shadow images are left: sampled by the lighting.
constexpr rg::ResourceState sampled{rg::PipelineStage::fragment_shader | rg::PipelineStage::compute_shader,
                                    rg::Access::shader_sampled_read, rg::ImageLayout::read_only_optimal};

// Tiled deferred measured fastest on both lavapipe and the H200 (docs/PERFORMANCE.md).
constexpr LightingPath fastest_lighting = LightingPath::deferred;

}  // namespace

SceneRenderer::SceneRenderer(vk::VulkanContext& context, const scene::Scene& scene, uint32_t frames_in_flight,
                             rg::Format frame_format, const RendererSettings& settings)
    : settings_(settings),
      lighting_(settings.lighting == LightingPath::automatic ? fastest_lighting : settings.lighting),
      gpu_scene_(context, scene.meshes, frames_in_flight),
      textures_(context, scene.textures),
      shadow_maps_(context),
      shadow_passes_(context, frames_in_flight),
      tone_map_(context, frame_format),
      light_records_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "light records") {
  switch (lighting_) {
    case LightingPath::every_light: every_light_.emplace(context, frames_in_flight, textures_); break;
    case LightingPath::forward:
      tiled_forward_.emplace(TiledForwardPass(context, textures_), LightTilesPass(context));
      break;
    case LightingPath::automatic:  // resolved above
    case LightingPath::deferred:
      deferred_.emplace(GBufferPass(context, frames_in_flight, textures_), LightTilesPass(context),
                        TiledLightingPass(context));
      break;
  }
}

void SceneRenderer::gather(const ecs::World& world) {
  gpu_scene_.gather(world);
  shadows::gather_lights(world, gpu_scene_.bounds(), settings_.lights, lights_);
}

void SceneRenderer::prepare(uint32_t slot) {
  shadow_maps_.fit(shadows::needed_storage(lights_));
  shadows::place_shadow_maps(lights_, shadow_maps_.size().maps.resolution,
                             shadow_maps_.size().cubes.resolution);
  gpu_scene_.upload(slot);
  const vk::Buffer& records = light_records_.write(slot, std::span<const shadows::GpuLight>(lights_.records));
  shadow_passes_.prepare(slot, lights_, gpu_scene_, settings_.cube_shadows, settings_.cull_casters);
  if (every_light_) every_light_->prepare(slot, gpu_scene_, records, shadow_maps_);
  if (tiled_forward_) tiled_forward_->forward.prepare(lights_.group_begin);
  if (deferred_) {
    deferred_->gbuffer.prepare(slot, gpu_scene_);
    deferred_->lighting.prepare(lights_.group_begin);
  }
}

RenderedFrame SceneRenderer::add_passes(rg::RenderGraph& graph, vk::GraphImports& imports,
                                        rg::ImageHandle frame, uint32_t slot, const scene::CameraPose& pose,
                                        const scene::Camera& lens) {
  ShadowPasses::Targets shadows{imports.import_image(graph, "shadow maps", shadow_maps_.maps(), sampled),
                                imports.import_image(graph, "shadow cubes", shadow_maps_.cubes(), sampled)};
  shadows = shadow_passes_.add_to(graph, shadows, lights_, gpu_scene_, slot, settings_.cube_shadows);

  const rg::ImageDesc& target = graph.resources()[frame.index].image;
  const glm::mat4 view_projection =
      projection_matrix(lens, float(target.width) / float(target.height)) * view_matrix(pose);
  const auto light_count = static_cast<uint32_t>(lights_.records.size());
  const LightTileGrid grid = LightTileGrid::of(target.width, target.height);
  const FrameConstants constants{view_projection, glm::vec4(pose.eye, ambient),
                                 glm::uvec4(light_count, grid.across, 0, 0)};
  const vk::Buffer& records = light_records_.buffer(slot);

  rg::ImageHandle lit_sum;
  rg::ImageHandle depth;
  if (every_light_) {
    const ForwardTargets lit = every_light_->add_to(graph, target.width, target.height, shadows.maps,
                                                    shadows.cubes, gpu_scene_, slot, constants);
    lit_sum = lit.lit_sum;
    depth = lit.depth;
  } else if (tiled_forward_) {
    depth = tiled_forward_->forward.add_depth_prepass(graph, target.width, target.height, gpu_scene_, slot,
                                                      constants);
    const LightTiles tiles =
        tiled_forward_->light_tiles.add_to(graph, depth, records, light_count, view_projection);
    lit_sum =
        tiled_forward_->forward
            .add_to(graph, depth, tiles, shadows.maps, shadows.cubes, records, gpu_scene_, slot, constants)
            .lit_sum;
  } else {
    const GBuffer gbuffer =
        deferred_->gbuffer.add_to(graph, target.width, target.height, gpu_scene_, slot, constants);
    const LightTiles tiles =
        deferred_->light_tiles.add_to(graph, gbuffer.depth, records, light_count, view_projection);
    lit_sum = deferred_->lighting.add_to(graph, gbuffer, tiles, shadows.maps, shadows.cubes, records,
                                         lights_.group_begin, pose.eye);
    depth = gbuffer.depth;
  }
  return {tone_map_.add_to(graph, lit_sum, frame, settings_.exposure), depth};
}

}  // namespace sg
