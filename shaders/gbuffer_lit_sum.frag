// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer (gbuffer.glsl) and the start of the lit sum, the ambient term times the base
// color (what lighting_ambient.glsl writes in a pass of its own); the background is the
// target's clear color. Where --lit-sum-start says the G-buffer (CPU devices by default), which
// saves the lighting a full-screen pass.
#include "gbuffer.glsl"

layout(location = 2) out vec4 out_lit_sum;

void main() {
  SurfacePoint p = write_gbuffer();
  // frame.ambient: the ambient term. Alpha: the shadow filter floor, none until
  // lighting_filter_floor.comp sets one.
  out_lit_sum = vec4(frame.ambient.rgb * p.base_color, 0.0);
}
