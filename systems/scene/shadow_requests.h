// SPDX-License-Identifier: MIT
#pragma once
// Asking for a light's shadow map to be drawn again, as HDRP's on-demand shadows do: for lights
// whose ShadowSettings::update is on_demand, the only way besides changing their shadow
// settings. A write of the settings (its change tick, which the gather reads), so the request
// is seen the next frame gathered, recorded like any other edit.
#include "ecs/world.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {

// False (nothing asked) when the entity has no ShadowSettings.
inline bool request_shadow_redraw(ecs::World& world, ecs::Entity light) {
  if (world.try_get<ShadowSettings>(light) == nullptr) return false;
  world.get_mut<ShadowSettings>(light);
  return true;
}

}  // namespace sg::scene
