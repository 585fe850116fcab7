#include "systems/scene/shadow_settings.h"

namespace sg::scene {

std::string_view to_string(ShadowAlgorithm algorithm) {
  switch (algorithm) {
    case ShadowAlgorithm::hard: return "hard";
    case ShadowAlgorithm::pcf: return "pcf";
    case ShadowAlgorithm::noise: return "noise";
    case ShadowAlgorithm::pcss: return "pcss";
    case ShadowAlgorithm::pcss_noise: return "pcss_noise";
  }
  return "unknown";
}

std::optional<ShadowAlgorithm> parse_shadow_algorithm(std::string_view name) {
  for (const ShadowAlgorithm algorithm : all_shadow_algorithms) {
    if (to_string(algorithm) == name) return algorithm;
  }
  return std::nullopt;
}

}  // namespace sg::scene
