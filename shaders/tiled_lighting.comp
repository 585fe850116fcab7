// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant storage_records LIGHT_RECORDS_IN_STORAGE
// Tiled deferred lighting of one light group in compute (tiled_lighting.glsl): one workgroup per
// tile that has lights of the group (light_tiles.comp's list; an indirect dispatch), each
// invocation one pixel, adding the group's lights to the lit sum. With RANKED_FILTERING the lit
// sum's alpha holds the pixel's filter floor (lighting_filter_floor.comp).
#include "tiled_lighting.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = hdr_binding, rgba16f) uniform image2D hdr;
layout(std430, set = 0, binding = group_tiles_binding) readonly buffer GroupTiles { uint group_tiles[]; };

void main() {
  uint tile = group_tiles[LIGHT_GROUP * frame.screen.w + gl_WorkGroupID.x];
  uvec2 tile_xy = uvec2(tile % frame.screen.z, tile / frame.screen.z);
  ivec2 pixel = ivec2(tile_xy * LIGHT_TILE_SIZE + gl_LocalInvocationID.xy);
  if (pixel.x >= int(frame.screen.x) || pixel.y >= int(frame.screen.y)) return;
  SurfacePoint p;
  vec3 position;
  if (!deferred_surface(pixel, p, position)) return;
  begin_contact_shadows(pixel);
  vec4 sum = imageLoad(hdr, pixel);
  float filter_floor = RANKED_FILTERING ? sum.a : 0.0;
  imageStore(hdr, pixel, sum + vec4(shade_tile_group(tile, p, position, filter_floor), 0.0));
}
