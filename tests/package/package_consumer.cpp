// SPDX-License-Identifier: MIT
// A user of the installed engine: builds the default scene through the engine's own headers
// and archives, and checks that its six lights are there, that the generated version header came
// along, and that a shader of its own was embedded with the installed shadowgraph_add_shaders.
#include <cstdint>
#include <cstdio>

#include "package/darken.comp.spv.h"
#include "shadowgraph/version.h"

#include "ecs/query.h"
#include "systems/scene/builtin_scene_builders.h"
#include "systems/scene/scene.h"
#include "systems/scene/shadow_settings.h"

int main() {
  const sg::scene::Scene scene = sg::scene::build_default_scene();
  int lights = 0;
  scene.world.query<const sg::scene::ShadowSettings>().for_each(
      [&](sg::ecs::Entity, const sg::scene::ShadowSettings&) { ++lights; });
  std::printf("Shadowgraph %s, %s: %d shadowed lights\n", SHADOWGRAPH_VERSION, scene.name.c_str(), lights);
  static_assert(SHADOWGRAPH_VERSION_MAJOR >= 0 && SHADOWGRAPH_VERSION_MINOR >= 0);
  constexpr uint32_t spirv_magic = 0x07230203;
  if (darken_comp[0] != spirv_magic) return 1;
  return lights == 6 ? 0 : 1;
}
