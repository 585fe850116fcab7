#pragma once
// The scene's shadow-casting lights as the reference needs them: where rays to them go, and how
// large the emitter is for the soft reference.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ecs/entity.h"
#include "systems/scene/enum_names.h"
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
};

// The lights whose ShadowSettings cast a shadow, in the world's order by type (spot,
// directional, cylinder, point). World transforms must be up to date.
std::vector<ReferenceLight> shadowed_lights(const scene::Scene& scene);

}  // namespace sg::reference
