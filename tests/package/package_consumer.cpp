// A user of the installed engine: builds the default scene through the engine's own headers
// and archives, and checks that its six lights are there.
#include <cstdio>

#include "ecs/query.h"
#include "systems/scene/builtin_scene_builders.h"
#include "systems/scene/scene.h"
#include "systems/scene/shadow_settings.h"

int main() {
  const sg::scene::Scene scene = sg::scene::build_default_scene();
  int lights = 0;
  scene.world.query<const sg::scene::ShadowSettings>().for_each(
      [&](sg::ecs::Entity, const sg::scene::ShadowSettings&) { ++lights; });
  std::printf("%s: %d shadowed lights\n", scene.name.c_str(), lights);
  return lights == 6 ? 0 : 1;
}
