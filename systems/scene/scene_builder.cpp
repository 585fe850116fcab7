// SPDX-License-Identifier: MIT
#include "systems/scene/scene_builder.h"

#include "systems/scene/mesh_instance.h"

namespace sg::scene {

ecs::Entity add_instance(Scene& scene, std::uint32_t mesh, const ecs::LocalTransform& local,
                         const Material& material) {
  const ecs::Entity entity = scene.world.create();
  scene.world.add<ecs::LocalTransform>(entity, local);
  scene.world.add<ecs::WorldTransform>(entity);
  scene.world.add<MeshInstance>(entity, mesh);
  scene.world.add<Material>(entity, material);
  return entity;
}

}  // namespace sg::scene
