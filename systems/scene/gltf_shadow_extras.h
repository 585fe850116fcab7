// SPDX-License-Identifier: MIT
#pragma once
// Per-light ShadowSettings from a glTF light's `extras` object (keys in gltf_lights.h).
#include <string>

#include <nlohmann/json.hpp>

#include "systems/scene/scene.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {

// `extras` may be anything (absent lights pass null); only an object contributes. `object`
// names the light in warnings, e.g. "KHR_lights_punctual.lights[2]".
ShadowSettings read_shadow_extras(const nlohmann::json& extras, const std::string& object, Scene& scene);

}  // namespace sg::scene
