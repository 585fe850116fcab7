#version 460
#extension GL_GOOGLE_include_directive : require
// Tiled deferred lighting of one light group (light_groups.glsl): one workgroup per tile that
// has lights of the group (light_tiles.comp's list; an indirect dispatch), each invocation one
// pixel, adding the tile's lights of the group to the lit sum. The group is a specialization
// constant, so the pipeline contains that group's shadow code and no other: a pixel pays for the
// lights of its tile and for the algorithm each uses.
#include "bindings.glsl"
#include "light_shading.glsl"
#include "light_tiles.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(constant_id = 0) const uint LIGHT_GROUP = 0u;

layout(set = 0, binding = gbuffer_position_binding) uniform sampler2D gbuffer_position;
layout(set = 0, binding = gbuffer_normal_binding) uniform sampler2D gbuffer_normal;
layout(set = 0, binding = gbuffer_albedo_binding) uniform sampler2D gbuffer_albedo;
layout(set = 0, binding = hdr_binding, rgba16f) uniform image2D hdr;
layout(std430, set = 0, binding = tile_lights_binding) readonly buffer TileLights { uint tile_lights[]; };
layout(std430, set = 0, binding = tile_ranges_binding) readonly buffer TileRanges { uvec2 tile_ranges[]; };
layout(std430, set = 0, binding = group_tiles_binding) readonly buffer GroupTiles { uint group_tiles[]; };

layout(push_constant) uniform Constants {
  vec4 camera_position;
  uvec4 screen;  // x width, y height, z tiles across, w tiles in all
} frame;

void main() {
  uint tile = group_tiles[LIGHT_GROUP * frame.screen.w + gl_WorkGroupID.x];
  uvec2 tile_xy = uvec2(tile % frame.screen.z, tile / frame.screen.z);
  ivec2 pixel = ivec2(tile_xy * LIGHT_TILE_SIZE + gl_LocalInvocationID.xy);
  if (pixel.x >= int(frame.screen.x) || pixel.y >= int(frame.screen.y)) return;
  vec4 albedo = texelFetch(gbuffer_albedo, pixel, 0);
  if (albedo.a == 0.0) return;  // background
  vec4 position = texelFetch(gbuffer_position, pixel, 0);
  vec4 normal = texelFetch(gbuffer_normal, pixel, 0);
  SurfacePoint p;
  p.normal = normal.xyz;
  p.to_viewer = normalize(frame.camera_position.xyz - position.xyz);
  p.base_color = albedo.rgb;
  p.specular = normal.w;
  p.shininess = position.w;

  // The tile has at least one light of the group (or it would not be dispatched), and a
  // do-while runs its body exactly that often on a CPU driver too.
  uvec2 range = tile_ranges[tile * LIGHT_GROUP_COUNT + LIGHT_GROUP];
  uint kind = group_shadow_kind(LIGHT_GROUP);
  uint algorithm = group_algorithm(LIGHT_GROUP);
  vec3 color = vec3(0.0);
  uint j = 0u;
  do {
    color += shade_light_as(light_at(tile_lights[range.x + j]), p, position.xyz, kind, algorithm);
    ++j;
  } while (j < range.y);
  imageStore(hdr, pixel, imageLoad(hdr, pixel) + vec4(color, 0.0));
}
