// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The picture: the lit sum, exposed and tone mapped (tone_map.glsl), into the sRGB frame.
#include "bindings.glsl"
#include "tone_map.glsl"

// Read as the storage image the lighting wrote, not through a sampler: on lavapipe the pass took
// 7.0-7.2 ms against 7.9-8.6 (1280x720, 2026-12-04).
layout(set = 0, binding = hdr_binding, rgba16f) uniform readonly image2D lit_sum;
layout(push_constant) uniform Constants { float exposure; } settings;

layout(location = 0) out vec4 out_color;

void main() {
  vec3 linear_color = imageLoad(lit_sum, ivec2(gl_FragCoord.xy)).rgb;
  out_color = vec4(tone_map(linear_color, settings.exposure), 1.0);  // the sRGB target encodes
}
