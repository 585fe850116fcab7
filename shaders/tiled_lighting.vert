#version 460
#extension GL_GOOGLE_include_directive : require
// The raster shape of tiled deferred lighting (tiled_lighting.glsl): instance i is the quad of
// the group's i-th tile with lights (light_tiles.comp's list; its indirect draw starts at the
// group's first slot, so gl_InstanceIndex indexes group_tiles directly). Six vertices, no buffer.
#include "bindings.glsl"
#include "light_tile_layout.glsl"

layout(std430, set = 0, binding = group_tiles_binding) readonly buffer GroupTiles { uint group_tiles[]; };

#include "tiled_lighting_frame.glsl"

void main() {
  uint tile = group_tiles[gl_InstanceIndex];
  // Two triangles: corners (0,0) (1,0) (0,1), (0,1) (1,0) (1,1).
  const uvec2 corners[6] = uvec2[](uvec2(0, 0), uvec2(1, 0), uvec2(0, 1), uvec2(0, 1), uvec2(1, 0), uvec2(1, 1));
  uvec2 pixel = (uvec2(tile % frame.screen.z, tile / frame.screen.z) + corners[gl_VertexIndex]) * LIGHT_TILE_SIZE;
  vec2 ndc = min(vec2(pixel), vec2(frame.screen.xy)) / vec2(frame.screen.xy) * 2.0 - 1.0;
  gl_Position = vec4(ndc, 0.0, 1.0);
}
