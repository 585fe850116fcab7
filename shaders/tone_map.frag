// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The picture: the lit sum, exposed and tone mapped (tone_map.glsl), into the sRGB frame.
#include "bindings.glsl"
#include "tone_map.glsl"

layout(set = 0, binding = hdr_binding) uniform sampler2D lit_sum;
layout(push_constant) uniform Constants { float exposure; } settings;

layout(location = 0) out vec4 out_color;

void main() {
  vec3 linear_color = texelFetch(lit_sum, ivec2(gl_FragCoord.xy), 0).rgb;
  out_color = vec4(tone_map(linear_color, settings.exposure), 1.0);  // the sRGB target encodes
}
