// SPDX-License-Identifier: MIT
// Tiled deferred lighting of one light group (light_groups.glsl): what tiled_lighting.comp reads
// and how it shades a pixel. The group is a specialization constant, so a pipeline contains that
// group's shadow code and no other: a pixel pays for the lights of its tile and for the algorithm
// each uses.
#ifndef SG_TILED_LIGHTING_GLSL
#define SG_TILED_LIGHTING_GLSL

#include "bindings.glsl"
#include "camera_depth.glsl"
#include "contact_shadows.glsl"
#include "gbuffer_layout.glsl"
#include "light_shading.glsl"
#include "light_tiles.glsl"
#include "tiled_lighting_frame.glsl"

layout(constant_id = 0) const uint LIGHT_GROUP = 0u;
// constant_id 4 (1 to 3 are light_shading.glsl's, material.glsl's and lights_interface.glsl's):
// the group has one light this frame, frame.lights.x, and a pixel of its tiles reads no light
// list: a CPU driver loads storage-buffer words lane by lane, and three a pixel were about 8 ms
// of the default scene's 140 on lavapipe (2026-11-30).
layout(constant_id = 4) const bool SINGLE_LIGHT = false;
// constant_id 5: the lit sum's alpha holds each pixel's filter floor (lighting_filter_floor.comp),
// below which a light takes the hard test instead of its own kernel (light_shading.glsl).
layout(constant_id = 5) const bool RANKED_FILTERING = false;
layout(set = 0, binding = gbuffer_normal_binding) uniform sampler2D gbuffer_normal;
layout(set = 0, binding = gbuffer_albedo_binding) uniform sampler2D gbuffer_albedo;
layout(std430, set = 0, binding = tile_lights_binding) readonly buffer TileLights { uint tile_lights[]; };
layout(std430, set = 0, binding = tile_ranges_binding) readonly buffer TileRanges { uvec2 tile_ranges[]; };

// This invocation's pixel of its 16x16 tile: each 32 invocations (an NVIDIA warp) take an 8x4
// block rather than two rows, so that a light's footprint and its shadow map's texels are shared
// by fewer, fuller warps (H200, 1920x1080, 100,000 lights: 10.84-10.86 ms a frame against
// 11.28-11.33 from afar, 23.55-23.57 against 24.46-24.50 at eye height, 2026-12-06). Eight
// consecutive invocations still make a row's eight pixels, a CPU driver's SIMD batch: lavapipe
// is level.
uvec2 pixel_in_tile() {
  uint i = gl_LocalInvocationIndex;
  return uvec2((i & 7u) | ((i >> 2u) & 8u), ((i >> 3u) & 3u) | ((i >> 4u) & 12u));
}

// The G-buffer's surface at `pixel` and its world position; false for the background.
bool deferred_surface(ivec2 pixel, out SurfacePoint p, out vec3 position) {
  float depth = texelFetch(scene_depth, pixel, 0).r;
  if (is_background_depth(depth)) return false;
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(frame.screen.xy) * 2.0 - 1.0;
  vec4 world = frame.inverse_view_projection * vec4(ndc, depth, 1.0);
  position = world.xyz / world.w;
  vec4 albedo = texelFetch(gbuffer_albedo, pixel, 0);
  vec4 normal = texelFetch(gbuffer_normal, pixel, 0);
  p.normal = octahedral_decode(normal.xy);
  p.to_viewer = normalize(frame.camera_position.xyz - position);
  p.base_color = albedo.rgb;
  p.specular = albedo.a;
  p.shininess = abs(normal.z);
  p.receives_shadow = normal.z > 0.0;
  p.light_layers = uint(normal.w);
  return true;
}

// The light group's lights of `tile` at the surface point. The tile has at least one (or it
// would not be drawn), and a do-while runs its body exactly that often on a CPU driver too. One
// call of the shading, a single light's too: a CPU driver inlines each call's whole shading code
// before the constants fold (group_slots.glsl): with a second call for single lights a group's
// pipeline took 0.52-0.96 s to build on lavapipe, with one 0.15-0.35 s (2026-12-06).
vec3 shade_tile_group(uint tile, SurfacePoint p, vec3 position, float filter_floor) {
  uint kind = group_shadow_kind(LIGHT_GROUP);
  uint algorithm = group_algorithm(LIGHT_GROUP);
  uvec2 range = SINGLE_LIGHT ? uvec2(0u, 1u) : tile_ranges[tile * LIGHT_GROUP_COUNT + LIGHT_GROUP];
  vec3 color = vec3(0.0);
  uint j = 0u;
  do {
    uint light = SINGLE_LIGHT ? frame.lights.x : tile_lights[range.x + j];
    color += shade_light_as(light_at(light), p, position, kind, algorithm, filter_floor, LIGHT_TYPES);
    ++j;
  } while (j < range.y);
  return color;
}

#endif
