// SPDX-License-Identifier: MIT
#pragma once
// The builders behind build_scene (builtin_scenes.h), one file each.
#include "systems/scene/scene.h"

namespace sg::scene {

struct BuiltinSceneParams;  // builtin_scenes.h

Scene build_default_scene();
Scene build_stress_scene(const BuiltinSceneParams& params);

}  // namespace sg::scene
