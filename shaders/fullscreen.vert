// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
#include "fullscreen.glsl"

void main() { emit_fullscreen_vertex(); }
