// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The depth prepass of masked materials: scene.vert's position, and no surface where the mask
// cuts it out (material.glsl), so that the forward pass after it finds the same holes.
#include "material.glsl"

void main() { cut_out(fragment_base_color().a); }
