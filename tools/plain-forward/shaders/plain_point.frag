// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The point light with a hard shadow: one fetch of its cube's distance, compared.
#include "plain_shading.glsl"

layout(set = 0, binding = 0) uniform samplerCube shadow_cube;  // distance / range

layout(location = 0) out vec4 out_color;

const float BIAS = 0.02;  // world units

void main() {
  vec3 from_light = in_position - frame.light_position_range.xyz;
  float stored = texture(shadow_cube, from_light).r * frame.light_position_range.w;
  float lit = length(from_light) - BIAS <= stored ? 1.0 : 0.0;
  out_color = shaded(1.0, 1.0 - lit);
}
