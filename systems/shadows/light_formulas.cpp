// SPDX-License-Identifier: MIT
#include "systems/shadows/light_formulas.h"

// The GLSL below reads as C++ once its types and built-ins name GLM's.
namespace sg::shadows::glsl {
using namespace glm;
using uint = std::uint32_t;
#include "shaders/light_formulas.glsl"
}  // namespace sg::shadows::glsl
