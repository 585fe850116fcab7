// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The static layers' restore pass (shadow_static_layers.glsl).
#define SAVE 0
#include "shadow_static_layers.glsl"
