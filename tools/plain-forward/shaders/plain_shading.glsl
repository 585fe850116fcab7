// SPDX-License-Identifier: MIT
// The engine's lighting model (docs/ALGORITHMS.md section 2: lighting.glsl's Blinn term, the
// linear range window and spot cone of light_formulas.glsl, tone_map.glsl's curve) for the one
// light, so that the plain renderer draws the engine's picture; `shade` is its shadow (1: dark).
#ifndef PLAIN_SHADING_GLSL
#define PLAIN_SHADING_GLSL

#include "light_formulas.glsl"
#include "lighting.glsl"
#include "plain_interface.glsl"
#include "tone_map.glsl"

const vec3 AMBIENT = vec3(0.15);  // the engine's default ambient term (--ambient)

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec3 in_color;
layout(location = 3) in vec2 in_specular_shininess;

// The fragment's color for a light whose cone factor at it is `cone`.
vec4 shaded(float cone, float shade) {
  SurfacePoint p;
  p.normal = normalize(in_normal);
  p.to_viewer = normalize(frame.camera_position.xyz - in_position);
  p.base_color = in_color;
  p.specular = in_specular_shininess.x;
  p.shininess = in_specular_shininess.y;
  vec3 to_light = frame.light_position_range.xyz - in_position;
  float distance = length(to_light);
  vec3 radiance = frame.light_color.rgb * falloff_linear_window(distance, frame.light_position_range.w) * cone;
  vec3 color = AMBIENT * in_color + blinn_light(p, to_light / distance, radiance, shade, 1.0, vec3(0.0));
  return vec4(tone_map(color, 1.0), 1.0);
}

#endif
