// SPDX-License-Identifier: MIT
#include "tools/reference/scene_triangles.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "ecs/hierarchy.h"
#include "ecs/query.h"
#include "ecs/transform.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_instance.h"

namespace sg::reference {

SceneTriangles scene_triangles(const scene::Scene& scene) {
  SceneTriangles out;
  const scene::MeshLibrary& library = scene.meshes;
  scene.world.query<const ecs::WorldTransform, const scene::MeshInstance>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform& world, const scene::MeshInstance& instance) {
        // Rays meet whole triangles: transparent surfaces are left out (the engine's shadows of
        // them are stochastic) and masked ones kept whole (no texture lookups).
        const scene::Material* material = scene.world.try_get<scene::Material>(entity);
        const bool caster =
            instance.casts_shadow && (material == nullptr || material->alpha_mode != scene::AlphaMode::blend);
        const scene::MeshRange& mesh = library.meshes.at(instance.mesh);
        for (uint32_t i = 0; i < mesh.index_count; ++i) {
          const uint32_t vertex = mesh.vertex_offset + library.indices[mesh.first_index + i];
          const glm::vec3 corner =
              glm::vec3(world.matrix * glm::vec4(library.vertices[vertex].position, 1.0f));
          out.surfaces.push_back(corner);
          if (caster) out.casters.push_back(corner);
        }
        if (caster)
          out.caster_layers.insert(out.caster_layers.end(), mesh.index_count / 3, instance.shadow_layers);
      });
  return out;
}

CasterScenes::CasterScenes(const SceneTriangles& triangles, std::span<const scene::LayerMask> masks) {
  for (const scene::LayerMask mask : masks) {
    if (scenes_[mask]) continue;
    std::vector<glm::vec3> corners;
    for (size_t t = 0; t < triangles.caster_layers.size(); ++t) {
      if (triangles.caster_layers[t] & mask)
        corners.insert(corners.end(), &triangles.casters[3 * t], &triangles.casters[3 * t + 3]);
    }
    scenes_[mask] = std::make_unique<RayScene>(corners);
  }
}

const RayScene& CasterScenes::of(scene::LayerMask mask) const {
  if (!scenes_[mask])
    throw std::logic_error("CasterScenes::of: no scene for caster mask " + std::to_string(mask));
  return *scenes_[mask];
}

uint32_t stop_casting(scene::Scene& scene, std::string_view name) {
  ecs::World& world = scene.world;
  const auto named = [&](ecs::Entity entity) {
    const scene::Name* found = world.try_get<scene::Name>(entity);
    return found && found->value.find(name) != std::string::npos;
  };
  std::vector<ecs::Entity> matches;
  std::as_const(world).query<const scene::MeshInstance>().for_each(
      [&](ecs::Entity entity, const scene::MeshInstance& instance) {
        if (!instance.casts_shadow) return;
        const ecs::Entity parent = ecs::parent_of(world, entity);
        if (named(entity) || (world.alive(parent) && named(parent))) matches.push_back(entity);
      });
  for (const ecs::Entity entity : matches) world.get_mut<scene::MeshInstance>(entity).casts_shadow = false;
  return static_cast<uint32_t>(matches.size());
}

}  // namespace sg::reference
