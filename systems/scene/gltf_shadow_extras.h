// SPDX-License-Identifier: MIT
#pragma once
// Per-light ShadowSettings from a glTF light's `extras` object (keys in gltf_lights.h).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "systems/scene/lights.h"
#include "systems/scene/scene.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {

// `extras` may be anything (absent lights pass null); only an object contributes. `object`
// names the light in warnings, e.g. "KHR_lights_punctual.lights[2]".
ShadowSettings read_shadow_extras(const nlohmann::json& extras, const std::string& object, Scene& scene);

// Whether glTF object `json` (a light, node or mesh) says it casts shadows (or, a node or mesh,
// receives them): `casts_shadow` (`receives_shadow`) in its extras (flat or in
// extras.shadowgraph, as read_shadow_extras reads them), else the draft KHR_lights_shadows
// extension's `castShadows` (`receiveShadows`); nullopt when it says neither. A value that is
// not true or false is reported (naming `object`) and ignored.
enum class ShadowFlag { casts, receives };
std::optional<bool> read_shadow_flag(const nlohmann::json& json, ShadowFlag flag, const std::string& object,
                                     Scene& scene);

// A point or spot light's falloff from its `extras` (`falloff`: "gltf_punctual" or
// "linear_window", flat or in extras.shadowgraph, as export_gltf writes it); nullopt when
// absent or not one of those (reported).
std::optional<FalloffMode> read_falloff(const nlohmann::json& extras, const std::string& object,
                                        Scene& scene);

// A cylinder light kept in a node's extras.shadowgraph.cylinder_light (glTF has no such type;
// export_gltf writes it there): its light and shadow settings, values checked as the light
// extras' are; nullopt when the node has none.
struct ImportedCylinder {
  CylinderLight light;
  ShadowSettings shadow;
};
std::optional<ImportedCylinder> read_cylinder_light(const nlohmann::json& node, const std::string& object,
                                                    Scene& scene);

}  // namespace sg::scene
