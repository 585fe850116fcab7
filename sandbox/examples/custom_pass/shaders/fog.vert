// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The engine's full-viewport triangle (its installed fullscreen.glsl).
#include "fullscreen.glsl"

void main() { emit_fullscreen_vertex(); }
