// SPDX-License-Identifier: MIT
#include "systems/renderer/renderer_settings.h"

namespace sg {

RendererSettings naive_baseline(RendererSettings settings) {
  settings.shadow_views = shadows::ShadowViewPath::per_light;
  settings.cache_shadows = false;
  settings.shadow_view_budget = 0;
  settings.shadow_budget_ms = 0.0f;
  settings.cube_shadows = shadows::CubeShadowMode::six_passes;
  settings.cull_casters = false;
  settings.lighting = LightingPath::every_light;
  return settings;
}

}  // namespace sg
