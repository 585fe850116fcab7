// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_shadow_extras.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace sg::scene {
namespace {

// Reads keys of one object: `extras` itself or its `shadowgraph` member, `prefix` naming it in
// warnings ("extras." or "extras.shadowgraph.").
struct ExtrasReader {
  const nlohmann::json& extras;
  std::string object;
  std::string prefix;
  Scene& scene;

  void report(const char* key, const std::string& problem) {
    warn(scene, object + ": " + prefix + key + " " + problem);
  }

  // The number under `key` clamped to [low, high]; nullopt (default kept) when absent or not a
  // finite number.
  std::optional<float> number(const char* key, float low, float high) {
    const auto found = extras.find(key);
    if (found == extras.end()) return std::nullopt;
    if (!found->is_number() || !std::isfinite(found->get<double>())) {
      report(key, "is not a finite number; using the default");
      return std::nullopt;
    }
    const double value = found->get<double>();
    const double clamped = std::clamp(value, double{low}, double{high});
    if (clamped != value) {
      report(key, std::to_string(value) + " is outside [" + std::to_string(low) + ", " +
                      std::to_string(high) + "]; clamped");
    }
    return static_cast<float>(clamped);
  }

  void read(const char* key, float& target, float low, float high) {
    if (const auto value = number(key, low, high)) target = *value;
  }
};

// Overrides `settings` with the keys `reader`'s object has.
void read_keys(ExtrasReader& reader, ShadowSettings& settings) {
  const nlohmann::json& extras = reader.extras;
  constexpr float unbounded = 1e30f;
  reader.read("bias", settings.constant_bias, 0.0f, unbounded);
  reader.read("slope_bias", settings.slope_bias, 0.0f, unbounded);
  reader.read("pcf_radius", settings.pcf_radius, 0.0f, 32.0f);
  reader.read("light_size", settings.light_size, 0.0f, unbounded);
  reader.read("density", settings.density, 0.0f, 1.0f);
  if (const auto resolution = reader.number("resolution", 16.0f, 16384.0f)) {
    settings.resolution = static_cast<std::uint32_t>(std::lround(*resolution));
  }
  if (const auto found = extras.find("algorithm"); found != extras.end()) {
    const auto parsed =
        found->is_string() ? parse_enum<ShadowAlgorithm>(found->get<std::string>()) : std::nullopt;
    if (parsed) {
      settings.algorithm = *parsed;
    } else {
      reader.report("algorithm", found->dump() + " is not one of hard, pcf, noise, pcss, pcss_noise; using " +
                                     std::string(to_string(settings.algorithm)));
    }
  }
  if (const auto found = extras.find("casts_shadow"); found != extras.end()) {
    if (found->is_boolean()) {
      settings.casts_shadow = found->get<bool>();
    } else {
      reader.report("casts_shadow",
                    "is not true or false; using " + std::string(settings.casts_shadow ? "true" : "false"));
    }
  }
  if (const auto found = extras.find("shadow_color"); found != extras.end()) {
    const bool valid = found->is_array() && found->size() == 3 &&
                       std::all_of(found->begin(), found->end(), [](const nlohmann::json& c) {
                         return c.is_number() && std::isfinite(c.get<double>());
                       });
    if (!valid) {
      reader.report("shadow_color", "is not an array of 3 finite numbers; keeping the default");
    } else {
      for (int c = 0; c < 3; ++c) {
        const float value = (*found)[c].get<float>();
        settings.shadow_color[c] = std::clamp(value, 0.0f, 1.0f);
        if (settings.shadow_color[c] != value)
          reader.report("shadow_color", "component outside [0, 1]; clamped");
      }
    }
  }
}

}  // namespace

ShadowSettings read_shadow_extras(const nlohmann::json& extras, const std::string& object, Scene& scene) {
  ShadowSettings settings;
  if (!extras.is_object()) return settings;
  ExtrasReader flat{extras, object, "extras.", scene};
  read_keys(flat, settings);
  if (const auto found = extras.find("shadowgraph"); found != extras.end()) {
    if (found->is_object()) {
      ExtrasReader namespaced{*found, object, "extras.shadowgraph.", scene};
      read_keys(namespaced, settings);
    } else {
      warn(scene, object + ": extras.shadowgraph is not an object; ignored");
    }
  }
  return settings;
}

std::optional<bool> read_shadow_flag(const nlohmann::json& json, ShadowFlag flag, const std::string& object,
                                     Scene& scene) {
  if (!json.is_object()) return std::nullopt;
  const std::string ours = flag == ShadowFlag::casts ? "casts_shadow" : "receives_shadow";
  const char* khr = flag == ShadowFlag::casts ? "castShadows" : "receiveShadows";
  const auto read = [&](const nlohmann::json& holder, const std::string& key,
                        const std::string& where) -> std::optional<bool> {
    if (!holder.is_object()) return std::nullopt;
    const auto found = holder.find(key);
    if (found == holder.end()) return std::nullopt;
    if (found->is_boolean()) return found->get<bool>();
    warn(scene, object + ": " + where + " is not true or false; ignored");
    return std::nullopt;
  };
  const nlohmann::json none;
  const auto member = [&](const nlohmann::json& holder, const char* key) -> const nlohmann::json& {
    const auto found = holder.is_object() ? holder.find(key) : holder.end();
    return holder.is_object() && found != holder.end() ? *found : none;
  };
  const nlohmann::json& extras = member(json, "extras");
  if (const auto value = read(member(extras, "shadowgraph"), ours, "extras.shadowgraph." + ours))
    return value;
  if (const auto value = read(extras, ours, "extras." + ours)) return value;
  return read(member(member(json, "extensions"), "KHR_lights_shadows"), khr,
              std::string("extensions.KHR_lights_shadows.") + khr);
}

std::optional<FalloffMode> read_falloff(const nlohmann::json& extras, const std::string& object,
                                        Scene& scene) {
  if (!extras.is_object()) return std::nullopt;
  const auto namespaced = extras.find("shadowgraph");
  const bool in_namespace =
      namespaced != extras.end() && namespaced->is_object() && namespaced->contains("falloff");
  const nlohmann::json& holder = in_namespace ? *namespaced : extras;
  const auto found = holder.find("falloff");
  if (found == holder.end()) return std::nullopt;
  if (*found == "gltf_punctual") return FalloffMode::gltf_punctual;
  if (*found == "linear_window") return FalloffMode::linear_window;
  warn(scene, object + ": extras." + (in_namespace ? "shadowgraph." : "") + "falloff " + found->dump() +
                  " is not gltf_punctual or linear_window; using gltf_punctual");
  return std::nullopt;
}

std::optional<ImportedCylinder> read_cylinder_light(const nlohmann::json& node, const std::string& object,
                                                    Scene& scene) {
  const auto extras = node.find("extras");
  if (extras == node.end() || !extras->is_object()) return std::nullopt;
  const auto namespaced = extras->find("shadowgraph");
  if (namespaced == extras->end() || !namespaced->is_object()) return std::nullopt;
  const auto found = namespaced->find("cylinder_light");
  if (found == namespaced->end()) return std::nullopt;
  ExtrasReader reader{*found, object, "extras.shadowgraph.cylinder_light.", scene};
  ImportedCylinder cylinder;
  read_keys(reader, cylinder.shadow);
  CylinderLight& light = cylinder.light;
  reader.read("intensity", light.intensity, 0.0f, 1e30f);
  reader.read("inner_radius", light.inner_radius, 0.0f, 1e30f);
  reader.read("outer_radius", light.outer_radius, 1e-4f, 1e30f);
  if (light.inner_radius >= light.outer_radius) {
    reader.report("inner_radius", "is not below outer_radius; using half of it");
    light.inner_radius = 0.5f * light.outer_radius;
  }
  if (const auto color = found->find("color"); color != found->end()) {
    if (color->is_array() && color->size() == 3 &&
        std::all_of(color->begin(), color->end(), [](const nlohmann::json& c) {
          return c.is_number() && std::isfinite(c.get<double>());
        })) {
      for (int c = 0; c < 3; ++c) light.color[c] = std::clamp((*color)[c].get<float>(), 0.0f, 1.0f);
    } else {
      reader.report("color", "is not an array of 3 finite numbers; using white");
    }
  }
  return cylinder;
}

}  // namespace sg::scene
