#include "systems/scene_renderer.h"

#include "systems/camera.h"
#include "systems/scene/lights.h"

namespace sg {

SceneRenderer::SceneRenderer(vk::VulkanContext& context, scene::Scene& scene,
                             uint32_t frames_in_flight)
    : scene_(scene), gpu_scene_(context, scene.meshes, frames_in_flight), forward_(context) {}

void SceneRenderer::update(uint32_t slot) { gpu_scene_.update(scene_.world, slot); }

ForwardTargets SceneRenderer::add_passes(rg::RenderGraph& graph, rg::ImageHandle colour,
                                         uint32_t slot, const scene::CameraPose& pose,
                                         const scene::Camera& lens) const {
  // Until the light list lands (issue 6), the first directional light is the only one shaded.
  glm::vec3 sun_direction{0.0f, -1.0f, 0.0f};
  glm::vec3 sun_radiance{0.0f};
  bool found = false;
  scene_.world.query<const ecs::WorldTransform, const scene::DirectionalLight>().for_each(
      [&](const ecs::WorldTransform& transform, const scene::DirectionalLight& light) {
        if (found) return;
        found = true;
        sun_direction = scene::light_direction(transform);
        sun_radiance = light.color * light.intensity;
      });

  const rg::ImageDesc& target = graph.resources()[colour.index].image;
  const float aspect = float(target.width) / float(target.height);
  const FrameConstants constants{projection_matrix(lens, aspect) * view_matrix(pose),
                                 glm::vec4(pose.eye, 1.0f), glm::vec4(sun_direction, 1.0f),
                                 glm::vec4(sun_radiance, ambient)};
  return forward_.add_to(graph, colour, gpu_scene_, slot, constants);
}

}  // namespace sg
