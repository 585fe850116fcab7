// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_lights.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "systems/scene/gltf_json.h"
#include "systems/scene/gltf_shadow_extras.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {
namespace {

constexpr const char* extension = "KHR_lights_punctual";

const nlohmann::json& light_array(const GltfSource& source) {
  static const nlohmann::json empty = nlohmann::json::array();
  const auto extensions = source.document.find("extensions");
  if (extensions == source.document.end() || !extensions->is_object()) return empty;
  const auto lights = extensions->find(extension);
  if (lights == extensions->end()) return empty;
  if (!lights->is_object()) throw SceneError(source.path, extension, "is not an object");
  return json_array(*lights, "lights", source.path);
}

glm::vec3 read_color(const nlohmann::json& light, const GltfSource& source, const std::string& object,
                     Scene& scene) {
  const auto found = light.find("color");
  if (found == light.end()) return glm::vec3(1.0f);
  const bool valid = found->is_array() && found->size() == 3 &&
                     std::all_of(found->begin(), found->end(), [](const nlohmann::json& c) {
                       return c.is_number() && std::isfinite(c.get<double>());
                     });
  if (!valid) throw SceneError(source.path, object, "color is not an array of 3 finite numbers");
  glm::vec3 color;
  for (int c = 0; c < 3; ++c) color[c] = (*found)[c].get<float>();
  const glm::vec3 clamped = glm::clamp(color, 0.0f, 1.0f);
  if (clamped != color) warn(scene, object + ": color component outside [0, 1]; clamped");
  return clamped;
}

SpotLight read_spot(const nlohmann::json& light, const GltfSource& source, const std::string& object,
                    Scene& scene) {
  SpotLight spot;
  spot.inner_cone = 0.0f;
  spot.outer_cone = glm::quarter_pi<float>();  // the extension's defaults
  const auto cone = light.find("spot");
  if (cone == light.end() || !cone->is_object()) {
    throw SceneError(source.path, object, "spot light without its required \"spot\" object");
  }
  const std::string cone_object = object + ".spot";
  spot.inner_cone = static_cast<float>(
      json_number(*cone, "innerConeAngle", source.path, cone_object).value_or(spot.inner_cone));
  spot.outer_cone = static_cast<float>(
      json_number(*cone, "outerConeAngle", source.path, cone_object).value_or(spot.outer_cone));
  if (spot.inner_cone < 0.0f) {
    throw SceneError(source.path, cone_object,
                     "innerConeAngle " + std::to_string(spot.inner_cone) + " is negative");
  }
  if (spot.outer_cone <= 0.0f || spot.outer_cone > glm::half_pi<float>()) {
    throw SceneError(source.path, cone_object,
                     "outerConeAngle " + std::to_string(spot.outer_cone) + " is outside (0, pi/2]");
  }
  if (spot.inner_cone > spot.outer_cone) {
    throw SceneError(source.path, cone_object,
                     "innerConeAngle " + std::to_string(spot.inner_cone) +
                         " is greater than outerConeAngle " + std::to_string(spot.outer_cone));
  }
  if (spot.inner_cone == spot.outer_cone) {
    warn(scene, cone_object + ": innerConeAngle equals outerConeAngle; inner set to 0.9 * outer");
    spot.inner_cone = 0.9f * spot.outer_cone;
  }
  return spot;
}

ImportedLight read_light(const nlohmann::json& light, const GltfSource& source, const std::string& object,
                         Scene& scene) {
  if (!light.is_object()) throw SceneError(source.path, object, "is not an object");
  const std::string type = json_string(light, "type", source.path, object).value_or("");
  const glm::vec3 color = read_color(light, source, object, scene);
  const float intensity =
      static_cast<float>(json_number(light, "intensity", source.path, object).value_or(1.0));
  if (intensity < 0.0f) {
    throw SceneError(source.path, object, "intensity " + std::to_string(intensity) + " is negative");
  }
  const auto declared_range = json_number(light, "range", source.path, object);
  if (declared_range && *declared_range <= 0.0) {
    throw SceneError(source.path, object,
                     "range " + std::to_string(*declared_range) + " must be greater than 0");
  }
  const float range = declared_range ? static_cast<float>(*declared_range) : effective_light_range(intensity);
  const std::string where = std::string(extension) + "." + object;
  ImportedLight imported;
  imported.shadow = read_light_shadow(light, where, scene);
  // glTF's own falloff, unless the extras keep another (export_gltf of a built-in scene's lights).
  const FalloffMode falloff = read_falloff(light, where, scene).value_or(FalloffMode::gltf_punctual);
  if (type == "point") {
    imported.light = PointLight{color, intensity, range, falloff};
  } else if (type == "spot") {
    SpotLight spot = read_spot(light, source, object, scene);
    spot.color = color;
    spot.intensity = intensity;
    spot.range = range;
    spot.falloff = falloff;
    imported.light = spot;
  } else if (type == "directional") {
    imported.light = DirectionalLight{color, intensity};
  } else {
    throw SceneError(source.path, object,
                     "unknown light type \"" + type + "\" (expected point, spot or directional)");
  }
  return imported;
}

}  // namespace

float effective_light_range(float intensity) { return std::max(16.0f * std::sqrt(intensity), 0.01f); }

std::vector<ImportedLight> read_gltf_lights(const GltfSource& source, Scene& scene) {
  const nlohmann::json& lights = light_array(source);
  std::vector<ImportedLight> imported;
  imported.reserve(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    imported.push_back(
        read_light(lights[i], source, std::string(extension) + ".lights[" + std::to_string(i) + "]", scene));
  }
  return imported;
}

std::optional<std::size_t> node_light(const GltfSource& source, std::size_t node, std::size_t light_count) {
  const nlohmann::json& nodes = json_array(source.document, "nodes", source.path);
  if (node >= nodes.size() || !nodes[node].is_object()) return std::nullopt;
  const auto extensions = nodes[node].find("extensions");
  if (extensions == nodes[node].end() || !extensions->is_object()) return std::nullopt;
  const auto reference = extensions->find(extension);
  if (reference == extensions->end()) return std::nullopt;
  const std::string object = indexed("nodes", node);
  const auto light = reference->is_object()
                         ? json_uint(*reference, "light", source.path, object + "." + extension)
                         : std::nullopt;
  if (!light || *light >= light_count) {
    throw SceneError(source.path, object,
                     std::string(extension) + " references light " +
                         (light ? std::to_string(*light) : std::string("(none)")) +
                         ", which does not exist (" + std::to_string(light_count) + " lights)");
  }
  return static_cast<std::size_t>(*light);
}

}  // namespace sg::scene
