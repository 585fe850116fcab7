#include "systems/scene_renderer.h"

#include <span>

#include "systems/camera.h"

namespace sg {
namespace {

constexpr const char* atlas_name = "shadow atlas";
constexpr const char* cubes_name = "shadow cubes";
// Where the shadow images are left: sampled by the lighting pass.
constexpr rg::ResourceState sampled{rg::PipelineStage::fragment_shader, rg::Access::shader_sampled_read,
                                    rg::ImageLayout::read_only_optimal};

}  // namespace

SceneRenderer::SceneRenderer(vk::VulkanContext& context, scene::Scene& scene,
                             uint32_t frames_in_flight, const RendererSettings& settings)
    : scene_(scene),
      settings_(settings),
      gpu_scene_(context, scene.meshes, frames_in_flight),
      textures_(context, scene.textures),
      atlas_(context),
      shadow_passes_(context, frames_in_flight),
      forward_(context, frames_in_flight, textures_),
      light_records_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "light records") {}

void SceneRenderer::update(uint32_t slot) {
  gpu_scene_.update(scene_.world, slot);
  gather_lights(scene_.world, gpu_scene_.bounds(), settings_.lights, lights_);
  const ShadowAtlas::Changes changes =
      atlas_.fit(static_cast<uint32_t>(lights_.maps.size()), lights_.map_size,
                 static_cast<uint32_t>(lights_.cubes.size()), lights_.cube_size);
  recreated_.maps = recreated_.maps || changes.maps;
  recreated_.cubes = recreated_.cubes || changes.cubes;
  place_shadow_maps(lights_, atlas_.maps_desc().width, atlas_.cubes_desc().width);
  const vk::Buffer& records =
      light_records_.write(slot, std::span<const shadows::GpuLight>(lights_.records));
  shadow_passes_.prepare(slot, lights_, gpu_scene_, settings_.cube_shadows);
  forward_.prepare(slot, gpu_scene_, records, atlas_);
}

ForwardTargets SceneRenderer::add_passes(rg::RenderGraph& graph, rg::ImportedStates& states,
                                         rg::ImageHandle colour, uint32_t slot,
                                         const scene::CameraPose& pose, const scene::Camera& lens) {
  if (recreated_.maps) states.forget(atlas_name);
  if (recreated_.cubes) states.forget(cubes_name);
  recreated_ = {};
  imported_ = {
      graph.import_image(atlas_name, atlas_.maps_desc(), states.initial_states(atlas_name), sampled),
      graph.import_image(cubes_name, atlas_.cubes_desc(), states.initial_states(cubes_name), sampled)};
  const ShadowPasses::Targets shadows =
      shadow_passes_.add_to(graph, imported_, lights_, gpu_scene_, slot, settings_.cube_shadows);

  const rg::ImageDesc& target = graph.resources()[colour.index].image;
  const float aspect = float(target.width) / float(target.height);
  const FrameConstants constants{projection_matrix(lens, aspect) * view_matrix(pose),
                                 glm::vec4(pose.eye, ambient),
                                 glm::uvec4(static_cast<uint32_t>(lights_.records.size()), 0, 0, 0)};
  return forward_.add_to(graph, colour, shadows.maps, shadows.cubes, gpu_scene_, slot, constants);
}

void SceneRenderer::bind_imports(vk::ImportedResources& imports) const {
  imports.bind(imported_.maps, atlas_.maps());
  imports.bind(imported_.cubes, atlas_.cubes());
}

}  // namespace sg
