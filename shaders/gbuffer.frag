// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer (gbuffer.glsl); the lit sum starts in a pass of its own (lighting_ambient.comp).
#include "gbuffer.glsl"

void main() { write_gbuffer(); }
