// SPDX-License-Identifier: MIT
// The G-buffer of tiled deferred lighting: what the light culling and the lighting passes need of
// each visible surface point. Shared by gbuffer.frag and gbuffer_lit_sum.frag.
#ifndef SG_GBUFFER_GLSL
#define SG_GBUFFER_GLSL

#include "gbuffer_layout.glsl"
#include "material.glsl"

// Positions come back from the depth buffer: every byte a pixel writes here costs raster
// hardware time on GPUs that have little of it (docs/PERFORMANCE.md).
layout(location = 0) out vec4 out_normal;  // gbuffer_layout.glsl
layout(location = 1) out vec4 out_albedo;  // rgb: base color; a: specular strength kS

// Writes the fragment's G-buffer texels and returns its surface.
SurfacePoint write_gbuffer() {
  SurfacePoint p = fragment_surface();
  out_normal = gbuffer_normal_texel(p.normal, p.shininess, p.receives_shadow, p.light_layers);
  out_albedo = vec4(p.base_color, p.specular);
  return p;
}

#endif
