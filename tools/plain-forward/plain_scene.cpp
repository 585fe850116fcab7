// SPDX-License-Identifier: MIT
#include "plain_scene.h"

#include <stdexcept>

#include "ecs/query.h"
#include "ecs/transform.h"
#include "systems/gpu/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/scene_queries.h"
#include "systems/scene/shadow_settings.h"

namespace sg::plain_forward {
namespace {

void add_instance(PlainScene& out, const scene::MeshLibrary& meshes, const scene::MeshInstance& instance,
                  const glm::mat4& model, const scene::Material& material) {
  const scene::MeshRange& mesh = meshes.meshes[instance.mesh];
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model)));
  const auto first = static_cast<uint32_t>(out.vertices.size());
  for (uint32_t v = 0; v < mesh.vertex_count; ++v) {
    const scene::Vertex& vertex = meshes.vertices[mesh.vertex_offset + v];
    out.vertices.push_back({glm::vec3(model * glm::vec4(vertex.position, 1.0f)),
                            glm::normalize(normal_matrix * vertex.normal),
                            glm::vec3(material.base_color),
                            {material.specular, material.shininess}});
  }
  for (uint32_t i = 0; i < mesh.index_count; ++i)
    out.indices.push_back(first + meshes.indices[mesh.first_index + i]);
}

}  // namespace

PlainScene flatten(const scene::Scene& scene, float aspect) {
  PlainScene out;
  scene.world.query<const scene::MeshInstance, const ecs::WorldTransform, const scene::Material>().for_each(
      [&](const scene::MeshInstance& instance, const ecs::WorldTransform& world,
          const scene::Material& material) {
        add_instance(out, scene.meshes, instance, world.matrix, material);
      });
  uint32_t lights = 0;
  scene.world.query<const scene::SpotLight, const ecs::WorldTransform, const scene::ShadowSettings>()
      .for_each([&](const scene::SpotLight& spot, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow) {
        out.light = {LightKind::spot,
                     scene::light_position(world),
                     scene::light_direction(world),
                     spot.range,
                     std::cos(spot.inner_cone),
                     std::cos(spot.outer_cone),
                     spot.color * spot.intensity,
                     shadow.resolution};
        ++lights;
      });
  scene.world.query<const scene::PointLight, const ecs::WorldTransform, const scene::ShadowSettings>()
      .for_each([&](const scene::PointLight& point, const ecs::WorldTransform& world,
                    const scene::ShadowSettings& shadow) {
        out.light = {LightKind::point,
                     scene::light_position(world),
                     {0.0f, 0.0f, -1.0f},
                     point.range,
                     1.0f,
                     0.0f,
                     point.color * point.intensity,
                     shadow.resolution};
        ++lights;
      });
  const scene::SceneStats stats = scene::scene_stats(scene);
  if (lights != 1 ||
      stats.point_lights + stats.spot_lights + stats.directional_lights + stats.cylinder_lights != 1) {
    throw std::runtime_error("a plain forward frame draws scenes of one spot or point light with a shadow");
  }
  const std::optional<ecs::Entity> camera = scene::first_camera(scene);
  if (!camera) throw std::runtime_error("the scene has no camera");
  const auto* lens = scene.world.try_get<scene::Camera>(*camera);
  const auto* placement = scene.world.try_get<ecs::WorldTransform>(*camera);
  const scene::CameraPose pose = scene::camera_pose(*placement);
  out.camera = projection_matrix(*lens, aspect) * view_matrix(pose);
  out.eye = pose.eye;
  return out;
}

}  // namespace sg::plain_forward
