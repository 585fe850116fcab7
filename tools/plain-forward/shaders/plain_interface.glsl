// SPDX-License-Identifier: MIT
// What the plain forward renderer's shaders share: one light, its shadow map's matrix, the camera.
#ifndef PLAIN_INTERFACE_GLSL
#define PLAIN_INTERFACE_GLSL

layout(set = 0, binding = 1) uniform Frame {
  mat4 camera;                // world -> the camera's clip space
  vec4 camera_position;
  mat4 light;                 // world -> the spot light's map (clip space); a point light's: unused
  vec4 light_position_range;  // xyz, range
  vec4 light_direction;       // xyz: the direction a spot light shines; w: cos(outer cone)
  vec4 light_color;           // rgb: color times intensity; w: cos(inner cone)
} frame;

#endif
