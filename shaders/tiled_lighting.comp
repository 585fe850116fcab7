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

layout(set = 0, binding = scene_depth_binding) uniform sampler2D scene_depth;
layout(set = 0, binding = gbuffer_normal_binding) uniform sampler2D gbuffer_normal;
layout(set = 0, binding = gbuffer_albedo_binding) uniform sampler2D gbuffer_albedo;
layout(set = 0, binding = hdr_binding, rgba16f) uniform image2D hdr;
layout(std430, set = 0, binding = tile_lights_binding) readonly buffer TileLights { uint tile_lights[]; };
layout(std430, set = 0, binding = tile_ranges_binding) readonly buffer TileRanges { uvec2 tile_ranges[]; };
layout(std430, set = 0, binding = group_tiles_binding) readonly buffer GroupTiles { uint group_tiles[]; };

layout(push_constant) uniform Constants {
  mat4 inverse_view_projection;  // the camera's: positions from the depth buffer
  vec4 camera_position;
  uvec4 screen;  // x width, y height, z tiles across, w tiles in all
} frame;

void main() {
  uint tile = group_tiles[LIGHT_GROUP * frame.screen.w + gl_WorkGroupID.x];
  uvec2 tile_xy = uvec2(tile % frame.screen.z, tile / frame.screen.z);
  ivec2 pixel = ivec2(tile_xy * LIGHT_TILE_SIZE + gl_LocalInvocationID.xy);
  if (pixel.x >= int(frame.screen.x) || pixel.y >= int(frame.screen.y)) return;
  float depth = texelFetch(scene_depth, pixel, 0).r;
  if (depth >= 1.0) return;  // background
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(frame.screen.xy) * 2.0 - 1.0;
  vec4 world = frame.inverse_view_projection * vec4(ndc, depth, 1.0);
  vec3 position = world.xyz / world.w;
  vec4 albedo = texelFetch(gbuffer_albedo, pixel, 0);
  vec4 normal = texelFetch(gbuffer_normal, pixel, 0);
  SurfacePoint p;
  p.normal = normal.xyz;
  p.to_viewer = normalize(frame.camera_position.xyz - position);
  p.base_color = albedo.rgb;
  p.specular = albedo.a;
  p.shininess = normal.w;
  p.pixel = uvec2(pixel);

  // The tile has at least one light of the group (or it would not be dispatched), and a
  // do-while runs its body exactly that often on a CPU driver too.
  uvec2 range = tile_ranges[tile * LIGHT_GROUP_COUNT + LIGHT_GROUP];
  uint kind = group_shadow_kind(LIGHT_GROUP);
  uint algorithm = group_algorithm(LIGHT_GROUP);
  vec3 color = vec3(0.0);
  uint j = 0u;
  do {
    color += shade_light_as(light_at(tile_lights[range.x + j]), p, position, kind, algorithm);
    ++j;
  } while (j < range.y);
  imageStore(hdr, pixel, imageLoad(hdr, pixel) + vec4(color, 0.0));
}
