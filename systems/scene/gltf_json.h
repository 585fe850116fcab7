// SPDX-License-Identifier: MIT
#pragma once
// Typed reads from the raw glTF JSON, for the checks that must run before (or instead of)
// tinygltf. A value of the wrong type is an error naming the object and key.
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace sg::scene {

// `document[key]` when it is an array; an empty array when absent; SceneError otherwise.
const nlohmann::json& json_array(const nlohmann::json& document, const char* key, const std::string& where);

// An unsigned integer property; nullopt when absent. Throws SceneError when present but not a
// non-negative integer. `object` names the JSON object in messages, e.g. "buffers[2]".
std::optional<std::uint64_t> json_uint(const nlohmann::json& object, const char* key,
                                       const std::string& where, const std::string& object_name);

// A number property (finite); nullopt when absent. Throws SceneError when present but not a
// finite number.
std::optional<double> json_number(const nlohmann::json& object, const char* key, const std::string& where,
                                  const std::string& object_name);

// A string property; nullopt when absent; SceneError when present but not a string.
std::optional<std::string> json_string(const nlohmann::json& object, const char* key,
                                       const std::string& where, const std::string& object_name);

// "name[index]", the way every message names a glTF object.
inline std::string indexed(const char* name, std::size_t index) {
  return std::string(name) + "[" + std::to_string(index) + "]";
}

}  // namespace sg::scene
