#version 460
#extension GL_GOOGLE_include_directive : require
// The lit sum's start (lighting_ambient.glsl) in compute, for lighting in compute.
#include "lighting_ambient.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = hdr_binding, rgba16f) uniform writeonly image2D hdr;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= int(frame.screen.x) || pixel.y >= int(frame.screen.y)) return;
  imageStore(hdr, pixel, lit_sum_start(pixel));
}
