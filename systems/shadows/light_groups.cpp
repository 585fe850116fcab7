// SPDX-License-Identifier: MIT
#include "systems/shadows/light_groups.h"

namespace sg::shadows {
namespace glsl {
using uint = std::uint32_t;
#include "shaders/light_groups.glsl"
}  // namespace glsl

static_assert(glsl::LIGHT_GROUP_COUNT == light_group_count);
static_assert(glsl::SHADOW_KIND_NONE == uint32_t(ShadowKind::none));
static_assert(glsl::SHADOW_KIND_MAP == uint32_t(ShadowKind::map));
static_assert(glsl::SHADOW_KIND_CUBE == uint32_t(ShadowKind::cube));

uint32_t light_group(ShadowKind kind, scene::ShadowAlgorithm algorithm) {
  return glsl::light_group(uint32_t(kind), uint32_t(algorithm));
}

ShadowKind group_shadow_kind(uint32_t group) { return ShadowKind(glsl::group_shadow_kind(group)); }

scene::ShadowAlgorithm group_algorithm(uint32_t group) {
  return scene::ShadowAlgorithm(glsl::group_algorithm(group));
}

}  // namespace sg::shadows
