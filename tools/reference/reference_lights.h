// SPDX-License-Identifier: MIT
#pragma once
// The scene's shadow-casting lights as the reference needs them: where rays to them go, and how
// large the emitter is for the soft reference.
#include <string>
#include <type_traits>
#include <vector>

#include <glm/glm.hpp>

#include "ecs/entity.h"
#include "ecs/world.h"
#include "systems/scene/enum_names.h"
#include "systems/scene/layers.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene.h"

namespace sg::reference {

enum class LightType { point, spot, directional, cylinder };

constexpr EnumNames<LightType, 4> enum_names(LightType) {
  return {{{LightType::point, "point"},
           {LightType::spot, "spot"},
           {LightType::directional, "directional"},
           {LightType::cylinder, "cylinder"}}};
}

struct ReferenceLight {
  ecs::Entity entity;
  std::string name;  // the scene's Name, or "<type> <n>"
  LightType type = LightType::point;
  glm::vec3 position{0.0f};   // point, spot, cylinder
  glm::vec3 direction{0.0f};  // unit, the way the light travels (spot, directional, cylinder)
  // ShadowSettings::light_size: the emitter's width in world units (point, spot), or its width
  // seen from one unit away (directional, cylinder), as the engine's PCSS reads it.
  float light_size = 0.0f;
  scene::LayerMask caster_mask = scene::all_layers;  // ShadowSettings::caster_mask: what shadows it
};

// Calls fn with the entity's light component, whichever type it is.
template <typename World, typename Fn>
void with_light(World& world, ecs::Entity entity, Fn fn) {
  if constexpr (std::is_const_v<World>) {
    if (const auto* l = world.template try_get<scene::PointLight>(entity)) return fn(*l);
    if (const auto* l = world.template try_get<scene::SpotLight>(entity)) return fn(*l);
    if (const auto* l = world.template try_get<scene::DirectionalLight>(entity)) return fn(*l);
    if (const auto* l = world.template try_get<scene::CylinderLight>(entity)) return fn(*l);
  } else {
    if (world.template has<scene::PointLight>(entity))
      return fn(world.template get_mut<scene::PointLight>(entity));
    if (world.template has<scene::SpotLight>(entity))
      return fn(world.template get_mut<scene::SpotLight>(entity));
    if (world.template has<scene::DirectionalLight>(entity))
      return fn(world.template get_mut<scene::DirectionalLight>(entity));
    if (world.template has<scene::CylinderLight>(entity))
      return fn(world.template get_mut<scene::CylinderLight>(entity));
  }
}

// Sets the entity's light component's intensity, whichever type it is.
void set_intensity(ecs::World& world, ecs::Entity entity, float intensity);

// The lights whose ShadowSettings cast a shadow, in the world's order by type (spot,
// directional, cylinder, point). World transforms must be up to date.
std::vector<ReferenceLight> shadowed_lights(const scene::Scene& scene);

}  // namespace sg::reference
