// SPDX-License-Identifier: MIT
#include "systems/scene/builtin_scenes.h"

#include <algorithm>
#include <string>

#include "ecs/transform_system.h"
#include "systems/scene/builtin_scene_builders.h"
#include "systems/scene/gltf_import.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {

Scene build_scene(std::string_view name, const BuiltinSceneParams& params) {
  if (!(params.moving_fraction >= 0.0f && params.moving_fraction <= 1.0f)) {
    throw SceneError("built-in scene", "moving_fraction",
                     std::to_string(params.moving_fraction) + " is outside [0, 1]");
  }
  if (!(params.light_spread > 0.0f && params.light_spread <= 1.0f)) {
    throw SceneError("built-in scene", "light_spread",
                     std::to_string(params.light_spread) + " is outside (0, 1]");
  }
  const auto unknown = [&]() -> Scene {
    std::string known;
    for (const std::string_view builtin : builtin_scene_names)
      known.append(known.empty() ? "" : ", ").append(builtin);
    throw SceneError("built-in scene", "\"" + std::string(name) + "\"", "unknown (known: " + known + ")");
  };
  Scene scene = name == "default"        ? build_default_scene()
                : name == "stress"       ? build_stress_scene(params)
                : name == "point-room"   ? build_point_room_scene()
                : name == "spot-columns" ? build_spot_columns_scene()
                                         : unknown();
  ecs::update_world_transforms(scene.world, 0);
  return scene;
}

Scene load_scene(std::string_view name_or_path, const BuiltinSceneParams& params) {
  const bool builtin = std::find(builtin_scene_names.begin(), builtin_scene_names.end(), name_or_path) !=
                       builtin_scene_names.end();
  return builtin ? build_scene(name_or_path, params) : load_gltf(std::string(name_or_path));
}

}  // namespace sg::scene
