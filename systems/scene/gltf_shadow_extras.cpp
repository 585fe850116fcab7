// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_shadow_extras.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace sg::scene {
namespace {

// `holder`'s member `key` when it is an object; nullptr otherwise.
const nlohmann::json* object_member(const nlohmann::json* holder, const char* key) {
  if (holder == nullptr || !holder->is_object()) return nullptr;
  const auto found = holder->find(key);
  return found != holder->end() && found->is_object() ? &*found : nullptr;
}

// Reads the keys of one object, `prefix` naming it in warnings ("extras.",
// "extras.shadowgraph.", ...). A wrong type or value is reported and the default or a clamped
// value kept.
struct ExtrasReader {
  const nlohmann::json& keys;
  std::string object;
  std::string prefix;
  Scene& scene;

  void report(const char* key, const std::string& problem) const {
    warn(scene, object + ": " + prefix + key + " " + problem);
  }

  const nlohmann::json* find(const char* key) const {
    const auto found = keys.find(key);
    return found == keys.end() ? nullptr : &*found;
  }

  // The number under `key` clamped to [low, high]; nullopt (default kept) when absent or not a
  // finite number.
  std::optional<float> number(const char* key, float low, float high) const {
    const nlohmann::json* found = find(key);
    if (found == nullptr) return std::nullopt;
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

  void read(const char* key, float& target, float low, float high) const {
    if (const auto value = number(key, low, high)) target = *value;
  }

  // A whole number: number() rounded.
  void read(const char* key, std::uint32_t& target, std::uint32_t low, std::uint32_t high) const {
    if (const auto value = number(key, float(low), float(high)))
      target = static_cast<std::uint32_t>(std::lround(*value));
  }

  // One of E's names; the default kept otherwise.
  template <NamedEnum E>
  void read_enum(const char* key, E& target) const {
    const nlohmann::json* found = find(key);
    if (found == nullptr) return;
    const auto parsed = found->is_string() ? parse_enum<E>(found->get<std::string>()) : std::nullopt;
    if (parsed) {
      target = *parsed;
    } else {
      report(key, found->dump() + " is not one of " + enum_name_list<E>() + "; using " +
                      std::string(to_string(target)));
    }
  }

  // A layer mask (layers.h): an integer from 0 to 255; nullopt when absent or not one (reported).
  std::optional<LayerMask> mask(const char* key) const {
    const nlohmann::json* found = find(key);
    if (found == nullptr) return std::nullopt;
    if (found->is_number_integer() && found->get<std::int64_t>() >= 0 &&
        found->get<std::int64_t>() <= all_layers) {
      return static_cast<LayerMask>(found->get<std::int64_t>());
    }
    report(key, found->dump() + " is not a layer mask (an integer from 0 to 255); ignored");
    return std::nullopt;
  }

  std::optional<bool> flag(const char* key) const {
    const nlohmann::json* found = find(key);
    if (found == nullptr) return std::nullopt;
    if (found->is_boolean()) return found->get<bool>();
    report(key, "is not true or false; ignored");
    return std::nullopt;
  }

  // An [r, g, b] color, each clamped to [0, 1].
  void color(const char* key, glm::vec3& target) const {
    const nlohmann::json* found = find(key);
    if (found == nullptr) return;
    const bool valid = found->is_array() && found->size() == 3 &&
                       std::all_of(found->begin(), found->end(), [](const nlohmann::json& c) {
                         return c.is_number() && std::isfinite(c.get<double>());
                       });
    if (!valid) {
      report(key, "is not an array of 3 finite numbers; keeping the default");
      return;
    }
    for (int c = 0; c < 3; ++c) {
      const float value = (*found)[c].get<float>();
      target[c] = std::clamp(value, 0.0f, 1.0f);
      if (target[c] != value) report(key, "component outside [0, 1]; clamped");
    }
  }
};

// The readers of a glTF object's extras, the flat keys first, then those of an
// extras.shadowgraph object, which win (absent ones are skipped).
std::array<std::optional<ExtrasReader>, 2> extras_readers(const nlohmann::json& json,
                                                          const std::string& object, Scene& scene) {
  std::array<std::optional<ExtrasReader>, 2> readers;
  const nlohmann::json* extras = object_member(&json, "extras");
  if (extras != nullptr) readers[0].emplace(ExtrasReader{*extras, object, "extras.", scene});
  if (const nlohmann::json* ours = object_member(extras, "shadowgraph")) {
    readers[1].emplace(ExtrasReader{*ours, object, "extras.shadowgraph.", scene});
  }
  return readers;
}

// Overrides `settings` with the keys `reader`'s object has, casts_shadow aside.
void read_keys(const ExtrasReader& reader, ShadowSettings& settings) {
  constexpr float unbounded = 1e30f;
  reader.read("bias", settings.constant_bias, 0.0f, unbounded);
  reader.read("slope_bias", settings.slope_bias, 0.0f, unbounded);
  reader.read("pcf_radius", settings.pcf_radius, 0.0f, 32.0f);
  reader.read("light_size", settings.light_size, 0.0f, unbounded);
  reader.read("density", settings.density, 0.0f, 1.0f);
  reader.read("resolution", settings.resolution, 16, 16384);
  reader.read("cascades", settings.cascades, 1, max_shadow_cascades);
  reader.read("pcf_half_width", settings.kernel.pcf_half_width, 1, max_pcf_half_width);
  reader.read("blocker_taps", settings.kernel.blocker_taps, 1, max_blocker_taps);
  reader.read("filter_taps", settings.kernel.filter_taps, 1, max_filter_taps);
  std::uint32_t noise_taps = settings.kernel.noise_taps;
  reader.read("noise_taps", noise_taps, 1, max_noise_taps);
  if (valid_noise_taps(noise_taps)) {
    settings.kernel.noise_taps = noise_taps;
  } else {
    reader.report("noise_taps", std::to_string(noise_taps) + " is not 4, 8 or 16; using " +
                                    std::to_string(settings.kernel.noise_taps));
  }
  reader.read("priority", settings.priority, -max_shadow_priority, max_shadow_priority);
  reader.read("contact_length", settings.contact_length, 0.0f, max_contact_length);
  reader.read_enum("update", settings.update);
  reader.read_enum("algorithm", settings.algorithm);
  reader.color("shadow_color", settings.shadow_color);
  if (const auto mask = reader.mask("caster_mask")) settings.caster_mask = *mask;
  if (const auto mask = reader.mask("light_mask")) settings.light_mask = *mask;
}

}  // namespace

ShadowSettings read_light_shadow(const nlohmann::json& light, const std::string& object, Scene& scene) {
  ShadowSettings settings;
  for (const std::optional<ExtrasReader>& reader : extras_readers(light, object, scene)) {
    if (reader) read_keys(*reader, settings);
  }
  const nlohmann::json* extras = object_member(&light, "extras");
  if (extras != nullptr && extras->contains("shadowgraph") &&
      object_member(extras, "shadowgraph") == nullptr) {
    warn(scene, object + ": extras.shadowgraph is not an object; ignored");
  }
  settings.casts_shadow = read_shadow_flag(light, ShadowFlag::casts, object, scene).value_or(true);
  return settings;
}

std::optional<bool> read_shadow_flag(const nlohmann::json& json, ShadowFlag flag, const std::string& object,
                                     Scene& scene) {
  const bool casts = flag == ShadowFlag::casts;
  const auto readers = extras_readers(json, object, scene);
  for (auto reader = readers.rbegin(); reader != readers.rend(); ++reader) {
    if (!*reader) continue;
    if (const auto value = (*reader)->flag(casts ? "casts_shadow" : "receives_shadow")) return value;
  }
  const nlohmann::json* khr = object_member(object_member(&json, "extensions"), "KHR_lights_shadows");
  if (khr == nullptr) return std::nullopt;
  return ExtrasReader{*khr, object, "extensions.KHR_lights_shadows.", scene}.flag(casts ? "castShadows"
                                                                                        : "receiveShadows");
}

nlohmann::json shadow_extras(const ShadowSettings& s) {
  return {{"algorithm", std::string(to_string(s.algorithm))},
          {"bias", s.constant_bias},
          {"slope_bias", s.slope_bias},
          {"pcf_radius", s.pcf_radius},
          {"light_size", s.light_size},
          {"density", s.density},
          {"shadow_color", {s.shadow_color.r, s.shadow_color.g, s.shadow_color.b}},
          {"resolution", s.resolution},
          {"cascades", s.cascades},
          {"update", std::string(to_string(s.update))},
          {"priority", s.priority},
          {"contact_length", s.contact_length},
          {"pcf_half_width", s.kernel.pcf_half_width},
          {"blocker_taps", s.kernel.blocker_taps},
          {"filter_taps", s.kernel.filter_taps},
          {"noise_taps", s.kernel.noise_taps},
          {"caster_mask", s.caster_mask},
          {"light_mask", s.light_mask},
          {"casts_shadow", s.casts_shadow}};
}

std::optional<LayerMask> read_mesh_layers(const nlohmann::json& json, MeshLayers which,
                                          const std::string& object, Scene& scene) {
  const auto readers = extras_readers(json, object, scene);
  for (auto reader = readers.rbegin(); reader != readers.rend(); ++reader) {
    if (!*reader) continue;
    if ((*reader)->find(to_key(which)) != nullptr) return (*reader)->mask(to_key(which));
  }
  return std::nullopt;
}

std::optional<FalloffMode> read_falloff(const nlohmann::json& light, const std::string& object,
                                        Scene& scene) {
  const auto readers = extras_readers(light, object, scene);
  for (auto reader = readers.rbegin(); reader != readers.rend(); ++reader) {
    if (!*reader) continue;
    const nlohmann::json* found = (*reader)->find("falloff");
    if (found == nullptr) continue;
    if (*found == "gltf_punctual") return FalloffMode::gltf_punctual;
    if (*found == "linear_window") return FalloffMode::linear_window;
    (*reader)->report("falloff",
                      found->dump() + " is not gltf_punctual or linear_window; using gltf_punctual");
    return std::nullopt;
  }
  return std::nullopt;
}

std::optional<ImportedCylinder> read_cylinder_light(const nlohmann::json& node, const std::string& object,
                                                    Scene& scene) {
  const nlohmann::json* found =
      object_member(object_member(object_member(&node, "extras"), "shadowgraph"), "cylinder_light");
  if (found == nullptr) return std::nullopt;
  const ExtrasReader reader{*found, object, "extras.shadowgraph.cylinder_light.", scene};
  ImportedCylinder cylinder;
  read_keys(reader, cylinder.shadow);
  cylinder.shadow.casts_shadow = reader.flag("casts_shadow").value_or(true);
  CylinderLight& light = cylinder.light;
  reader.read("intensity", light.intensity, 0.0f, 1e30f);
  reader.read("inner_radius", light.inner_radius, 0.0f, 1e30f);
  reader.read("outer_radius", light.outer_radius, 1e-4f, 1e30f);
  if (light.inner_radius >= light.outer_radius) {
    reader.report("inner_radius", "is not below outer_radius; using half of it");
    light.inner_radius = 0.5f * light.outer_radius;
  }
  reader.color("color", light.color);
  return cylinder;
}

}  // namespace sg::scene
