#version 460
#extension GL_GOOGLE_include_directive : require
// The lit sum's start (lighting_ambient.glsl) as a full-screen fragment pass (fullscreen.vert),
// for lighting in fragment passes.
#include "lighting_ambient.glsl"

layout(location = 0) out vec4 out_color;

void main() { out_color = lit_sum_start(ivec2(gl_FragCoord.xy)); }
