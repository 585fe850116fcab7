// SPDX-License-Identifier: MIT
#version 460
// One face of the point light's cube: the distance to the light goes to a color target.
layout(location = 0) in vec3 in_position;
layout(location = 0) out vec3 out_from_light;
layout(push_constant) uniform Constants {
  mat4 view_projection;       // world -> the face's clip space
  vec4 light_position_range;  // xyz, range
} constants;

void main() {
  out_from_light = in_position - constants.light_position_range.xyz;
  gl_Position = constants.view_projection * vec4(in_position, 1.0);
}
