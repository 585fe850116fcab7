// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// Forward lighting: ambient plus every light of the frame at every pixel, each with its own
// shadow algorithm (docs/ALGORITHMS.md sections 2 and 4), into the linear HDR sum that tone mapping
// turns into the picture.
#include "light_shading.glsl"
#include "material.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  SurfacePoint p = fragment_surface();
  vec3 color = frame.ambient.rgb * p.base_color;
  color += shade_lights(p, in_world_position, frame.counts.x);
  out_color = vec4(color, 1.0);
}
