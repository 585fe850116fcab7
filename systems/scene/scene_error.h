// SPDX-License-Identifier: MIT
#pragma once
// The one exception the scene library throws for input it refuses (a malformed glTF file, an
// unknown built-in scene name, a bad --camera string). The message always reads
// "<where>: <object>: <problem>", e.g. "box.gltf: accessors[3]: ... exceeds bufferViews[1]",
// so a user can find the offending object without a debugger.
#include <stdexcept>
#include <string>

namespace sg::scene {

class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& where, const std::string& object, const std::string& problem)
      : std::runtime_error(where + ": " + object + ": " + problem) {}
};

}  // namespace sg::scene
