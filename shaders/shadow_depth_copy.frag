// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// Each atlas texel of a view drawn in compute takes its depth from the view's square of the depth
// buffer (shadow_depth_copy.vert; the bits shadow_raster.comp's atomicMin left there). The
// pipeline writes depth whatever the atlas held (compare ALWAYS).
#include "bindings.glsl"

layout(std430, set = 0, binding = shadow_depths_binding) readonly buffer Depths { uint depths[]; };

layout(location = 0) noperspective in vec2 in_texel;
layout(location = 1) flat in uvec2 in_place;  // the square's texel (0, 0) and its row pitch

void main() {
  uvec2 texel = uvec2(in_texel);
  gl_FragDepth = uintBitsToFloat(depths[in_place.x + texel.y * in_place.y + texel.x]);
}
