// The start of tiled deferred lighting's lit sum, every pixel: the ambient term kA * IA times the
// G-buffer's base colour, or the background colour where no surface was drawn. Written here
// rather than as a G-buffer target: on GPUs with little raster hardware the G-buffer's cost
// follows the bytes it writes per pixel (docs/PERFORMANCE.md). Two shapes like tiled lighting's
// (tiled_lighting.glsl): a compute dispatch (lighting_ambient.comp) and a full-screen fragment
// pass (lighting_ambient.frag).
#ifndef SG_LIGHTING_AMBIENT_GLSL
#define SG_LIGHTING_AMBIENT_GLSL

#include "bindings.glsl"

layout(set = 0, binding = gbuffer_albedo_binding) uniform sampler2D gbuffer_albedo;
layout(set = 0, binding = scene_depth_binding) uniform sampler2D scene_depth;

layout(push_constant) uniform Constants {
  vec4 background_ambient;  // rgb: the background colour; w: the ambient term
  uvec4 screen;             // x width, y height
} frame;

vec4 lit_sum_start(ivec2 pixel) {
  bool background = texelFetch(scene_depth, pixel, 0).r >= 1.0;
  vec3 colour = background ? frame.background_ambient.rgb
                           : frame.background_ambient.w * texelFetch(gbuffer_albedo, pixel, 0).rgb;
  return vec4(colour, 1.0);
}

#endif
