#include "systems/scene/scene.h"

#include <cstdio>
#include <utility>

namespace sg::scene {

void warn(Scene& scene, std::string text) {
  std::fprintf(stderr, "warning: %s: %s\n", scene.name.c_str(), text.c_str());
  scene.warnings.push_back(std::move(text));
}

}  // namespace sg::scene
