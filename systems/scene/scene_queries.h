// SPDX-License-Identifier: MIT
#pragma once
// Facts about a scene that the renderer, the sandbox's --stats and the tests ask for. They
// read WorldTransform, so they assume transforms are up to date (they are when load_gltf or
// build_scene return; after animating, run ecs::update_world_transforms first).
#include <cstdint>
#include <optional>

#include "ecs/entity.h"
#include "systems/scene/aabb.h"
#include "systems/scene/scene.h"

namespace sg::scene {

struct SceneStats {
  std::uint64_t entities = 0;
  std::uint64_t mesh_instances = 0;
  std::uint64_t triangles = 0;  // summed over instances
  std::uint32_t point_lights = 0;
  std::uint32_t spot_lights = 0;
  std::uint32_t directional_lights = 0;
  std::uint32_t cylinder_lights = 0;
  std::uint32_t shadow_casting_lights = 0;  // lights whose ShadowSettings::casts_shadow is set
};

SceneStats scene_stats(const Scene& scene);

// The world-space box around every mesh instance; empty when there are none.
Aabb scene_bounds(const Scene& scene);

// The first camera entity created (glTF: the first camera node in depth-first order).
std::optional<ecs::Entity> first_camera(const Scene& scene);

}  // namespace sg::scene
