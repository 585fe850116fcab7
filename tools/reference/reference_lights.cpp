// SPDX-License-Identifier: MIT
#include "tools/reference/reference_lights.h"

#include "ecs/query.h"
#include "ecs/transform.h"
#include "systems/scene/lights.h"
#include "systems/scene/shadow_settings.h"

namespace sg::reference {
namespace {

template <typename Light>
void collect(const scene::Scene& scene, LightType type, std::vector<ReferenceLight>& out) {
  scene.world.query<const ecs::WorldTransform, const Light, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const ecs::WorldTransform& world, const Light&,
          const scene::ShadowSettings& shadow) {
        if (!shadow.casts_shadow) return;
        ReferenceLight light;
        light.entity = entity;
        const scene::Name* name = scene.world.try_get<scene::Name>(entity);
        light.name = name && !name->value.empty()
                         ? name->value
                         : std::string(to_string(type)) + " " + std::to_string(out.size());
        light.type = type;
        light.position = scene::light_position(world);
        light.direction = scene::light_direction(world);
        light.light_size = shadow.light_size;
        light.caster_mask = shadow.caster_mask;
        out.push_back(std::move(light));
      });
}

}  // namespace

std::vector<ReferenceLight> shadowed_lights(const scene::Scene& scene) {
  std::vector<ReferenceLight> out;
  collect<scene::SpotLight>(scene, LightType::spot, out);
  collect<scene::DirectionalLight>(scene, LightType::directional, out);
  collect<scene::CylinderLight>(scene, LightType::cylinder, out);
  collect<scene::PointLight>(scene, LightType::point, out);
  return out;
}

void set_intensity(ecs::World& world, ecs::Entity entity, float intensity) {
  with_light(world, entity, [&](auto& light) { light.intensity = intensity; });
}

}  // namespace sg::reference
