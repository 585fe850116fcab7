// SPDX-License-Identifier: MIT
#pragma once
// Small helpers for code that builds scenes entity by entity (the built-in scenes, tests).
#include <string>

#include "ecs/transform.h"
#include "systems/scene/material.h"
#include "systems/scene/scene.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {

// A root entity drawing `mesh` with `material`, placed by `local`.
ecs::Entity add_instance(Scene& scene, std::uint32_t mesh, const ecs::LocalTransform& local,
                         const Material& material);

// A root light entity: `light` is a PointLight, SpotLight, DirectionalLight or CylinderLight.
template <typename Light>
ecs::Entity add_light(Scene& scene, const Light& light, const ecs::LocalTransform& local,
                      const ShadowSettings& shadow, std::string name) {
  const ecs::Entity entity = scene.world.create();
  scene.world.add<ecs::LocalTransform>(entity, local);
  scene.world.add<ecs::WorldTransform>(entity);
  scene.world.add<Light>(entity, light);
  scene.world.add<ShadowSettings>(entity, shadow);
  scene.world.add<Name>(entity, std::move(name));
  return entity;
}

}  // namespace sg::scene
