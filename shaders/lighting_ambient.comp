// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The start of tiled deferred lighting's lit sum, every pixel: the ambient term kA * IA times the
// G-buffer's base color, or the background color where no surface was drawn. Written here
// rather than as a G-buffer target: on GPUs with little raster hardware the G-buffer's cost
// follows the bytes it writes per pixel (docs/PERFORMANCE.md).
#include "bindings.glsl"
#include "camera_depth.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = gbuffer_albedo_binding) uniform sampler2D gbuffer_albedo;
layout(set = 0, binding = scene_depth_binding) uniform sampler2D scene_depth;
layout(set = 0, binding = hdr_binding, rgba16f) uniform writeonly image2D hdr;

layout(push_constant) uniform Constants {
  vec4 background;  // rgb: the background color
  vec4 ambient;     // rgb: the ambient term kA * IA
  uvec4 screen;     // x width, y height
} frame;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= int(frame.screen.x) || pixel.y >= int(frame.screen.y)) return;
  bool background = is_background_depth(texelFetch(scene_depth, pixel, 0).r);
  vec3 color = background ? frame.background.rgb : frame.ambient.rgb * texelFetch(gbuffer_albedo, pixel, 0).rgb;
  imageStore(hdr, pixel, vec4(color, 0.0));  // alpha: no filter floor (lighting_filter_floor.comp)
}
