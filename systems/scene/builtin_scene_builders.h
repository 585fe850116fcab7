// SPDX-License-Identifier: MIT
#pragma once
// The builders behind build_scene (builtin_scenes.h), one file each.
#include "systems/scene/scene.h"

namespace sg::scene {

struct BuiltinSceneParams;  // builtin_scenes.h

Scene build_default_scene();
Scene build_stress_scene(const BuiltinSceneParams& params);
Scene build_point_room_scene();
Scene build_spot_columns_scene();

}  // namespace sg::scene
