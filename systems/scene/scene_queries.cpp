// SPDX-License-Identifier: MIT
#include "systems/scene/scene_queries.h"

#include "ecs/query.h"
#include "ecs/transform.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {
namespace {

template <typename Light>
std::uint32_t count_lights(const ecs::World& world, std::uint32_t& casting) {
  std::uint32_t count = 0;
  world.query<const Light, const ShadowSettings>().for_each([&](const Light&, const ShadowSettings& shadow) {
    ++count;
    if (shadow.casts_shadow) ++casting;
  });
  return count;
}

}  // namespace

SceneStats scene_stats(const Scene& scene) {
  SceneStats stats;
  stats.entities = scene.world.entity_count();
  scene.world.query<const MeshInstance>().for_each([&](const MeshInstance& instance) {
    ++stats.mesh_instances;
    stats.triangles += triangle_count(scene.meshes.meshes[instance.mesh]);
  });
  stats.point_lights = count_lights<PointLight>(scene.world, stats.shadow_casting_lights);
  stats.spot_lights = count_lights<SpotLight>(scene.world, stats.shadow_casting_lights);
  stats.directional_lights = count_lights<DirectionalLight>(scene.world, stats.shadow_casting_lights);
  stats.cylinder_lights = count_lights<CylinderLight>(scene.world, stats.shadow_casting_lights);
  return stats;
}

Aabb scene_bounds(const Scene& scene) {
  Aabb bounds;
  scene.world.query<const MeshInstance, const ecs::WorldTransform>().for_each(
      [&](const MeshInstance& instance, const ecs::WorldTransform& world) {
        grow(bounds, transformed(scene.meshes.meshes[instance.mesh].bounds, world.matrix));
      });
  return bounds;
}

std::optional<ecs::Entity> first_camera(const Scene& scene) {
  std::optional<ecs::Entity> found;
  scene.world.query<const Camera>().for_each([&](ecs::Entity entity, const Camera&) {
    if (!found) found = entity;
  });
  return found;
}

}  // namespace sg::scene
