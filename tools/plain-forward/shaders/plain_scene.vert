// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
#include "plain_interface.glsl"

layout(location = 0) in vec3 in_position;  // world space
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec3 in_color;
layout(location = 3) in vec2 in_specular_shininess;
layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec3 out_color;
layout(location = 3) flat out vec2 out_specular_shininess;

void main() {
  out_position = in_position;
  out_normal = in_normal;
  out_color = in_color;
  out_specular_shininess = in_specular_shininess;
  gl_Position = frame.camera * vec4(in_position, 1.0);
}
