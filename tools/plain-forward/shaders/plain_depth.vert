// SPDX-License-Identifier: MIT
#version 460
// The spot light's depth map: positions are already in world space.
layout(location = 0) in vec3 in_position;
layout(push_constant) uniform Constants {
  mat4 view_projection;  // world -> the map's clip space
  vec4 light_position_range;
} constants;

void main() { gl_Position = constants.view_projection * vec4(in_position, 1.0); }
