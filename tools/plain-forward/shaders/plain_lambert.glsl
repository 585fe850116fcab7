// SPDX-License-Identifier: MIT
// Ambient plus Lambert diffuse of the one light with a linear falloff, `lit` of it unshadowed.
#ifndef PLAIN_LAMBERT_GLSL
#define PLAIN_LAMBERT_GLSL

#include "plain_interface.glsl"

const float AMBIENT = 0.15;

vec3 lambert(vec3 position, vec3 normal, vec3 color, float cone, float lit) {
  vec3 to_light = frame.light_position_range.xyz - position;
  float distance = length(to_light);
  float n_dot_l = max(dot(normalize(normal), to_light / distance), 0.0);
  float falloff = clamp(1.0 - distance / frame.light_position_range.w, 0.0, 1.0);
  return color * (AMBIENT + lit * n_dot_l * cone * falloff * frame.light_color.rgb);
}

#endif
