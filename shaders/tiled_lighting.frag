#version 460
#extension GL_GOOGLE_include_directive : require
// Tiled deferred lighting of one light group as a fragment pass (tiled_lighting.glsl) over the
// quads of the tiles that have lights of the group (tiled_lighting.vert); the output is added to
// the lit sum by the pipeline's blending.
#include "tiled_lighting.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  SurfacePoint p;
  vec3 position;
  if (!deferred_surface(pixel, p, position)) discard;
  uvec2 tile_xy = uvec2(pixel) / LIGHT_TILE_SIZE;
  out_color = vec4(shade_tile_group(tile_xy.y * frame.screen.z + tile_xy.x, p, position), 0.0);
}
