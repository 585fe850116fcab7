// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The point light with a hard shadow: one fetch of its cube's distance, compared.
#include "plain_lambert.glsl"

layout(set = 0, binding = 0) uniform samplerCube shadow_cube;  // distance / range

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec3 in_color;
layout(location = 0) out vec4 out_color;

const float BIAS = 0.02;  // world units

void main() {
  vec3 from_light = in_position - frame.light_position_range.xyz;
  float stored = texture(shadow_cube, from_light).r * frame.light_position_range.w;
  float lit = length(from_light) - BIAS <= stored ? 1.0 : 0.0;
  out_color = vec4(lambert(in_position, in_normal, in_color, 1.0, lit), 1.0);
}
