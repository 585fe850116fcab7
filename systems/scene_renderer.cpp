#include "systems/scene_renderer.h"

#include <span>

#include "systems/camera.h"

namespace sg {
namespace {

// Where the shadow images are left: sampled by the lighting pass.
constexpr rg::ResourceState sampled{rg::PipelineStage::fragment_shader, rg::Access::shader_sampled_read,
                                    rg::ImageLayout::read_only_optimal};

}  // namespace

SceneRenderer::SceneRenderer(vk::VulkanContext& context, const scene::Scene& scene, uint32_t frames_in_flight,
                             const RendererSettings& settings)
    : settings_(settings),
      gpu_scene_(context, scene.meshes, frames_in_flight),
      textures_(context, scene.textures),
      shadow_maps_(context),
      shadow_passes_(context, frames_in_flight),
      forward_(context, frames_in_flight, textures_),
      light_records_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "light records") {}

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
  shadow_passes_.prepare(slot, lights_, gpu_scene_, settings_.cube_shadows);
  forward_.prepare(slot, gpu_scene_, records, shadow_maps_);
}

ForwardTargets SceneRenderer::add_passes(rg::RenderGraph& graph, vk::GraphImports& imports,
                                         rg::ImageHandle colour, uint32_t slot, const scene::CameraPose& pose,
                                         const scene::Camera& lens) {
  ShadowPasses::Targets shadows{imports.import_image(graph, "shadow maps", shadow_maps_.maps(), sampled),
                                imports.import_image(graph, "shadow cubes", shadow_maps_.cubes(), sampled)};
  shadows = shadow_passes_.add_to(graph, shadows, lights_, gpu_scene_, slot, settings_.cube_shadows);

  const rg::ImageDesc& target = graph.resources()[colour.index].image;
  const float aspect = float(target.width) / float(target.height);
  const FrameConstants constants{projection_matrix(lens, aspect) * view_matrix(pose),
                                 glm::vec4(pose.eye, ambient),
                                 glm::uvec4(static_cast<uint32_t>(lights_.records.size()), 0, 0, 0)};
  return forward_.add_to(graph, colour, shadows.maps, shadows.cubes, gpu_scene_, slot, constants);
}

}  // namespace sg
