// SPDX-License-Identifier: MIT
#pragma once
// Shadow settings, shadow flags, falloff and cylinder lights from glTF objects' `extras` and the
// draft KHR_lights_shadows (keys in systems/scene/README.md). Nothing here fails an import: a
// wrong type or value is reported, naming `object`, and the default or a clamped value used.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "systems/scene/layers.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene.h"
#include "systems/scene/shadow_settings.h"

namespace sg::scene {

// The ShadowSettings of glTF light `light` (KHR_lights_punctual.lights[i]): its extras' keys,
// flat or in an extras.shadowgraph object whose keys win, and casts_shadow as read_shadow_flag
// reads it. `object` names the light in warnings, e.g. "KHR_lights_punctual.lights[2]".
ShadowSettings read_light_shadow(const nlohmann::json& light, const std::string& object, Scene& scene);

// Whether glTF object `json` (a light, node or mesh) says it casts shadows (or, a node or mesh,
// receives them): `casts_shadow` (`receives_shadow`) in its extras (flat or in
// extras.shadowgraph, whose keys win), else the draft KHR_lights_shadows
// extension's `castShadows` (`receiveShadows`); nullopt when it says neither. A value that is
// not true or false is reported (naming `object`) and ignored.
enum class ShadowFlag { casts, receives };
std::optional<bool> read_shadow_flag(const nlohmann::json& json, ShadowFlag flag, const std::string& object,
                                     Scene& scene);

// `settings` under the keys read_light_shadow reads (export_gltf writes them so; the sidecar too,
// with constant_bias for bias).
nlohmann::json shadow_extras(const ShadowSettings& settings);

// A node's or mesh's layers (MeshInstance::light_layers or ::shadow_layers): the integer 0 to
// 255 under `light_layers` or `shadow_layers` in its extras (flat or in extras.shadowgraph, whose
// keys win); nullopt when it has none, or not such an integer (reported, naming `object`).
enum class MeshLayers { light, shadow };
constexpr const char* to_key(MeshLayers which) {
  return which == MeshLayers::light ? "light_layers" : "shadow_layers";
}
std::optional<LayerMask> read_mesh_layers(const nlohmann::json& json, MeshLayers which,
                                          const std::string& object, Scene& scene);

// A point or spot light's falloff from its extras (`falloff`: "gltf_punctual" or
// "linear_window", flat or in extras.shadowgraph, as export_gltf writes it); nullopt when
// absent or not one of those (reported).
std::optional<FalloffMode> read_falloff(const nlohmann::json& light, const std::string& object, Scene& scene);

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
