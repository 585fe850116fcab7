// SPDX-License-Identifier: MIT
#version 460
layout(location = 0) in vec3 in_from_light;
layout(location = 0) out float out_distance;  // distance / range
layout(push_constant) uniform Constants {
  mat4 view_projection;
  vec4 light_position_range;
} constants;

void main() { out_distance = length(in_from_light) / constants.light_position_range.w; }
