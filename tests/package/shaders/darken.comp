// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// A pass of the user's own, compiled by the installed shadowgraph_add_shaders: it includes the
// engine's binding numbers by name from the installed GLSL.
#include "bindings.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = hdr_binding, rgba16f) uniform image2D hdr;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(hdr)))) return;
  imageStore(hdr, pixel, imageLoad(hdr, pixel) * 0.5);
}
