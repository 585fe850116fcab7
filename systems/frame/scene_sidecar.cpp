// SPDX-License-Identifier: MIT
#include "systems/frame/scene_sidecar.h"

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "shadowgraph/version.h"

#include "ecs/query.h"
#include "ecs/transform.h"
#include "ecs/transform_system.h"
#include "systems/scene/gltf_shadow_extras.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene_builder.h"
#include "systems/scene/shadow_settings.h"

namespace sg {
namespace {

using Json = nlohmann::ordered_json;

Json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// Every light of the scene with its sidecar name, in the scene's order.
std::vector<std::pair<std::string, ecs::Entity>> named_lights(const scene::Scene& scene) {
  std::vector<std::pair<std::string, ecs::Entity>> lights;
  scene.world.query<const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const scene::ShadowSettings&) {
        const scene::Name* name = scene.world.try_get<scene::Name>(entity);
        lights.emplace_back(
            name && !name->value.empty() ? name->value : "light " + std::to_string(lights.size()), entity);
      });
  return lights;
}

const char* falloff_name(scene::FalloffMode mode) {
  return mode == scene::FalloffMode::gltf_punctual ? "gltf_punctual" : "linear_window";
}

Json light_json(const scene::Scene& scene, const std::string& name, ecs::Entity entity) {
  const ecs::World& world = scene.world;
  const ecs::LocalTransform& local = world.get<ecs::LocalTransform>(entity);
  Json light = {{"name", name},
                {"position", vec(local.translation)},
                {"rotation", {local.rotation.x, local.rotation.y, local.rotation.z, local.rotation.w}}};
  if (const auto* point = world.try_get<scene::PointLight>(entity)) {
    light.update({{"type", "point"},
                  {"color", vec(point->color)},
                  {"intensity", point->intensity},
                  {"range", point->range},
                  {"falloff", falloff_name(point->falloff)}});
  } else if (const auto* spot = world.try_get<scene::SpotLight>(entity)) {
    light.update({{"type", "spot"},
                  {"color", vec(spot->color)},
                  {"intensity", spot->intensity},
                  {"range", spot->range},
                  {"inner_cone", spot->inner_cone},
                  {"outer_cone", spot->outer_cone},
                  {"falloff", falloff_name(spot->falloff)}});
  } else if (const auto* sun = world.try_get<scene::DirectionalLight>(entity)) {
    light.update({{"type", "directional"}, {"color", vec(sun->color)}, {"intensity", sun->intensity}});
  } else if (const auto* beam = world.try_get<scene::CylinderLight>(entity)) {
    light.update({{"type", "cylinder"},
                  {"color", vec(beam->color)},
                  {"intensity", beam->intensity},
                  {"inner_radius", beam->inner_radius},
                  {"outer_radius", beam->outer_radius}});
  }
  const scene::ShadowSettings& s = world.get<scene::ShadowSettings>(entity);
  // The extras' keys, but for the constant bias, which the sidecar's first form named in full.
  Json shadow = scene::shadow_extras(s);
  shadow["constant_bias"] = shadow["bias"];
  shadow.erase("bias");
  light["shadow"] = std::move(shadow);
  return light;
}

// One light of the sidecar, read and checked before the scene changes.
struct SidecarLight {
  std::string name;
  std::string type;
  ecs::LocalTransform local;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float range = 10.0f;
  float inner = 0.0f;
  float outer = 1.0f;
  scene::FalloffMode falloff = scene::FalloffMode::linear_window;
  scene::ShadowSettings shadow;
};

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& entry, const std::string& problem) const {
    throw std::runtime_error(path_ + ": " + entry + ": " + problem);
  }
  float number(const Json& object, const char* key, const std::string& entry, float fallback) const {
    if (!object.contains(key)) return fallback;
    const Json& value = object.at(key);
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      fail(entry + "." + key, "is not a finite number");
    return value.get<float>();
  }
  // An integer from `low` to `high`, refused as not `what`.
  template <class T>
  T integer(const Json& object, const char* key, const std::string& entry, T fallback, int64_t low,
            int64_t high, const std::string& what) const {
    if (!object.contains(key)) return fallback;
    const Json& value = object.at(key);
    if (!value.is_number_integer() || value.get<int64_t>() < low || value.get<int64_t>() > high)
      fail(entry + "." + key, "is not " + what);
    return static_cast<T>(value.get<int64_t>());
  }
  uint32_t count(const Json& object, const char* key, const std::string& entry, uint32_t fallback,
                 uint32_t most) const {
    return integer(object, key, entry, fallback, 1, most, "a whole number from 1 to " + std::to_string(most));
  }
  scene::LayerMask mask(const Json& object, const char* key, const std::string& entry,
                        scene::LayerMask fallback) const {
    return integer(object, key, entry, fallback, 0, scene::all_layers,
                   "a layer mask (an integer from 0 to 255)");
  }
  template <NamedEnum E>
  E name(const Json& object, const char* key, const std::string& entry, E fallback) const {
    if (!object.contains(key)) return fallback;
    const Json& value = object.at(key);
    const auto parsed = value.is_string() ? parse_enum<E>(value.get<std::string>()) : std::nullopt;
    if (!parsed) fail(entry + "." + key, "is not one of " + enum_name_list<E>());
    return *parsed;
  }
  glm::vec3 vector(const Json& object, const char* key, const std::string& entry, glm::vec3 fallback) const {
    if (!object.contains(key)) return fallback;
    const Json& value = object.at(key);
    if (!value.is_array() || value.size() != 3) fail(entry + "." + key, "is not an array of 3 numbers");
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) {
      if (!value[i].is_number()) fail(entry + "." + key, "is not an array of 3 numbers");
      v[i] = value[i].get<float>();
    }
    return v;
  }

  SidecarLight light(const Json& json, const std::string& entry) const {
    if (!json.is_object()) fail(entry, "is not an object");
    SidecarLight light;
    if (!json.contains("name") || !json.at("name").is_string()) fail(entry, "has no name");
    light.name = json.at("name").get<std::string>();
    light.type = json.value("type", "");
    if (light.type != "point" && light.type != "spot" && light.type != "directional" &&
        light.type != "cylinder") {
      fail(entry + ".type", "is not point, spot, directional or cylinder");
    }
    light.local.translation = vector(json, "position", entry, glm::vec3(0.0f));
    if (json.contains("rotation")) {
      const Json& r = json.at("rotation");
      if (!r.is_array() || r.size() != 4) fail(entry + ".rotation", "is not a quaternion x, y, z, w");
      const glm::quat q(r[3].get<float>(), r[0].get<float>(), r[1].get<float>(), r[2].get<float>());
      if (!(glm::length(q) > 0.0f)) fail(entry + ".rotation", "is a zero quaternion");
      light.local.rotation = glm::normalize(q);
    }
    light.color = vector(json, "color", entry, glm::vec3(1.0f));
    light.intensity = number(json, "intensity", entry, 1.0f);
    light.range = number(json, "range", entry, 10.0f);
    if (light.range <= 0.0f) fail(entry + ".range", "is not positive");
    light.inner = number(json, light.type == "cylinder" ? "inner_radius" : "inner_cone", entry, 0.0f);
    light.outer = number(json, light.type == "cylinder" ? "outer_radius" : "outer_cone", entry, 0.785f);
    if (light.inner < 0.0f || light.outer <= light.inner)
      fail(entry, "inner must be at least 0 and below outer");
    light.falloff = json.value("falloff", "linear_window") == std::string("gltf_punctual")
                        ? scene::FalloffMode::gltf_punctual
                        : scene::FalloffMode::linear_window;
    if (json.contains("shadow")) {
      const Json& s = json.at("shadow");
      const std::string where = entry + ".shadow";
      if (!s.is_object()) fail(where, "is not an object");
      light.shadow.algorithm = name(s, "algorithm", where, light.shadow.algorithm);
      light.shadow.constant_bias = number(s, "constant_bias", where, light.shadow.constant_bias);
      light.shadow.slope_bias = number(s, "slope_bias", where, light.shadow.slope_bias);
      light.shadow.pcf_radius = number(s, "pcf_radius", where, light.shadow.pcf_radius);
      light.shadow.light_size = number(s, "light_size", where, light.shadow.light_size);
      light.shadow.density = number(s, "density", where, light.shadow.density);
      light.shadow.shadow_color = vector(s, "shadow_color", where, light.shadow.shadow_color);
      const float resolution = number(s, "resolution", where, float(light.shadow.resolution));
      if (resolution < 1.0f || resolution > 16384.0f) fail(where + ".resolution", "is not within 1 .. 16384");
      light.shadow.resolution = static_cast<uint32_t>(resolution);
      const float cascades = number(s, "cascades", where, float(light.shadow.cascades));
      if (cascades < 1.0f || cascades > float(scene::max_shadow_cascades)) {
        fail(where + ".cascades", "is not within 1 .. " + std::to_string(scene::max_shadow_cascades));
      }
      light.shadow.cascades = static_cast<uint32_t>(cascades);
      light.shadow.update = name(s, "update", where, light.shadow.update);
      light.shadow.priority = number(s, "priority", where, light.shadow.priority);
      if (std::abs(light.shadow.priority) > scene::max_shadow_priority) {
        fail(where + ".priority", "is not within -4 .. 4");
      }
      light.shadow.contact_length = number(s, "contact_length", where, light.shadow.contact_length);
      if (light.shadow.contact_length < 0.0f || light.shadow.contact_length > scene::max_contact_length) {
        fail(where + ".contact_length", "is not within 0 .. 10");
      }
      scene::ShadowKernel& kernel = light.shadow.kernel;
      kernel.pcf_half_width =
          count(s, "pcf_half_width", where, kernel.pcf_half_width, scene::max_pcf_half_width);
      kernel.blocker_taps = count(s, "blocker_taps", where, kernel.blocker_taps, scene::max_blocker_taps);
      kernel.filter_taps = count(s, "filter_taps", where, kernel.filter_taps, scene::max_filter_taps);
      kernel.noise_taps = count(s, "noise_taps", where, kernel.noise_taps, scene::max_noise_taps);
      if (!scene::valid_noise_taps(kernel.noise_taps)) fail(where + ".noise_taps", "is not 4, 8 or 16");
      light.shadow.caster_mask = mask(s, "caster_mask", where, light.shadow.caster_mask);
      light.shadow.light_mask = mask(s, "light_mask", where, light.shadow.light_mask);
      light.shadow.casts_shadow = s.value("casts_shadow", true);
    }
    return light;
  }

 private:
  std::string path_;
};

void write_light(scene::Scene& scene, ecs::Entity entity, const SidecarLight& light) {
  ecs::World& world = scene.world;
  world.get_mut<ecs::LocalTransform>(entity) = light.local;
  world.get_mut<scene::ShadowSettings>(entity) = light.shadow;
  if (light.type == "point") {
    world.add<scene::PointLight>(entity,
                                 scene::PointLight{light.color, light.intensity, light.range, light.falloff});
  } else if (light.type == "spot") {
    world.add<scene::SpotLight>(entity, scene::SpotLight{light.color, light.intensity, light.range,
                                                         light.inner, light.outer, light.falloff});
  } else if (light.type == "directional") {
    world.add<scene::DirectionalLight>(entity, scene::DirectionalLight{light.color, light.intensity});
  } else {
    world.add<scene::CylinderLight>(
        entity, scene::CylinderLight{light.color, light.intensity, light.inner, light.outer});
  }
}

}  // namespace

std::filesystem::path sidecar_path(const std::string& scene) { return scene + ".shadowgraph.json"; }

void save_sidecar(const std::filesystem::path& path, const scene::Scene& scene,
                  const scene::CameraPose& pose) {
  Json lights = Json::array();
  for (const auto& [name, entity] : named_lights(scene)) lights.push_back(light_json(scene, name, entity));
  const Json document = {
      {"schema_version", sidecar_schema_version},
      {"generator", "Shadowgraph " SHADOWGRAPH_VERSION},
      {"camera", {{"eye", vec(pose.eye)}, {"target", vec(pose.target)}, {"up", vec(pose.up)}}},
      {"lights", lights}};
  std::ofstream file(path);
  file << document.dump(2) << '\n';
  if (!file) throw std::runtime_error("cannot write " + path.string());
}

void apply_sidecar(const std::filesystem::path& path, scene::Scene& scene, scene::CameraPose& pose) {
  const std::string where = path.string();
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read " + where);
  Json document;
  try {
    document = Json::parse(file);
  } catch (const nlohmann::json::exception& error) {
    throw std::runtime_error(where + ": not JSON: " + error.what());
  }
  const Reader reader(where);
  if (!document.is_object()) reader.fail("(top)", "is not an object");
  if (document.contains("schema_version")) {
    const Json& version = document.at("schema_version");
    if (!version.is_number_integer() || version.get<int>() < 1)
      reader.fail("schema_version", "is not a whole number from 1");
    if (version.get<int>() > sidecar_schema_version) {
      reader.fail("schema_version", "is " + std::to_string(version.get<int>()) +
                                        ": written by a newer Shadowgraph; this one reads up to " +
                                        std::to_string(sidecar_schema_version));
    }
  }
  // Read and check everything before anything changes.
  std::vector<SidecarLight> lights;
  if (document.contains("lights")) {
    const Json& list = document.at("lights");
    if (!list.is_array()) reader.fail("lights", "is not an array");
    for (size_t i = 0; i < list.size(); ++i)
      lights.push_back(reader.light(list[i], "lights[" + std::to_string(i) + "]"));
  }
  std::optional<scene::CameraPose> camera;
  if (document.contains("camera")) {
    const Json& c = document.at("camera");
    camera = scene::CameraPose{reader.vector(c, "eye", "camera", pose.eye),
                               reader.vector(c, "target", "camera", pose.target),
                               reader.vector(c, "up", "camera", glm::vec3(0, 1, 0))};
    if (camera->eye == camera->target) reader.fail("camera", "eye and target are the same point");
  }

  std::unordered_map<std::string, ecs::Entity> existing;
  for (const auto& [name, entity] : named_lights(scene)) existing.emplace(name, entity);
  for (const SidecarLight& light : lights) {
    ecs::Entity entity;
    if (auto found = existing.find(light.name); found != existing.end()) {
      entity = found->second;
      existing.erase(found);
      // The light keeps its entity; its type may have changed.
      scene.world.remove<scene::PointLight>(entity);
      scene.world.remove<scene::SpotLight>(entity);
      scene.world.remove<scene::DirectionalLight>(entity);
      scene.world.remove<scene::CylinderLight>(entity);
    } else {
      entity = scene::add_light(scene, scene::PointLight{}, light.local, light.shadow, light.name);
      scene.world.remove<scene::PointLight>(entity);
    }
    write_light(scene, entity, light);
  }
  for (const auto& [name, entity] : existing) scene.world.destroy(entity);  // the user removed them
  if (camera) pose = *camera;
  ecs::update_world_transforms(scene.world, 0);
}

}  // namespace sg
