// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_json.h"

#include <cmath>

#include "systems/scene/scene_error.h"

namespace sg::scene {

const nlohmann::json& json_array(const nlohmann::json& document, const char* key, const std::string& where) {
  static const nlohmann::json empty = nlohmann::json::array();
  const auto found = document.find(key);
  if (found == document.end()) return empty;
  if (!found->is_array()) throw SceneError(where, key, "is not an array");
  return *found;
}

std::optional<std::uint64_t> json_uint(const nlohmann::json& object, const char* key,
                                       const std::string& where, const std::string& object_name) {
  const auto found = object.find(key);
  if (found == object.end()) return std::nullopt;
  if (found->is_number_unsigned()) return found->get<std::uint64_t>();
  if (found->is_number_integer() && found->get<std::int64_t>() >= 0) {
    return static_cast<std::uint64_t>(found->get<std::int64_t>());
  }
  throw SceneError(where, object_name, std::string(key) + " is not a non-negative integer");
}

std::optional<double> json_number(const nlohmann::json& object, const char* key, const std::string& where,
                                  const std::string& object_name) {
  const auto found = object.find(key);
  if (found == object.end()) return std::nullopt;
  if (!found->is_number() || !std::isfinite(found->get<double>())) {
    throw SceneError(where, object_name, std::string(key) + " is not a finite number");
  }
  return found->get<double>();
}

std::optional<std::string> json_string(const nlohmann::json& object, const char* key,
                                       const std::string& where, const std::string& object_name) {
  const auto found = object.find(key);
  if (found == object.end()) return std::nullopt;
  if (!found->is_string()) throw SceneError(where, object_name, std::string(key) + " is not a string");
  return found->get<std::string>();
}

}  // namespace sg::scene
