// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant storage_records LIGHT_RECORDS_IN_STORAGE
// Ranked shadow filtering's floor, every pixel, before the light groups' passes: the shadow
// weight (light_shading.glsl) of the FILTERED_LIGHTS-th heaviest of the tile's lights that filter
// (the groups of pcf, noise, pcss and pcss_noise), written to the lit sum's alpha
// (tiled_lighting.comp reads it). Lights lighter than that take the hard test instead of their
// kernel, so a pixel runs at most FILTERED_LIGHTS kernels however many lights overlap it; 0 where
// fewer reach it, and every light filters.
#include "tiled_lighting.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

// constant_id 6 (0 to 5 are tiled_lighting.glsl's and what it includes).
const uint MOST_FILTERED_LIGHTS = 16u;
layout(constant_id = 6) const uint FILTERED_LIGHTS = 8u;  // 1 to MOST_FILTERED_LIGHTS

layout(set = 0, binding = hdr_binding, rgba16f) uniform image2D hdr;

// The largest finite half float, less a margin: heavier floors are held there (every light
// at least that heavy filters).
const float MOST_FLOOR = 65000.0;

// The tile's filtering lights, a batch at a time (light_batch.glsl): fetched by each pixel the
// records cost the texture units more than loading them once for the tile (H200, 1920x1080,
// 2026-12-02: lighting 10.33 -> 9.42 ms with 16,384 lights over 20k triangles, 5.56 -> 5.38 with
// 1,024 on a sixteenth of the stress hall; docs/PERFORMANCE.md). Tiles with few lights skip the
// pass, barriers and all.
const uint LIGHT_BATCH = 256u;  // one light an invocation
#include "light_batch.glsl"

// Whether `group`'s lights run a filter kernel (pcf, noise, pcss, pcss_noise).
bool group_filters(uint group) {
  return group_shadow_kind(group) != SHADOW_KIND_NONE && group_algorithm(group) != SHADOW_HARD;
}

void main() {
  uint tile = gl_WorkGroupID.y * frame.screen.z + gl_WorkGroupID.x;
  // A tile with no more filtering lights than the rank keeps the floor the lit sum started with,
  // none: every light filters.
  uint filtering = 0u;
  for (uint group = 0u; group < LIGHT_GROUP_COUNT; ++group) {
    if (group_filters(group)) filtering += tile_ranges[tile * LIGHT_GROUP_COUNT + group].y;
  }
  if (filtering <= FILTERED_LIGHTS) return;
  ivec2 pixel = ivec2(gl_WorkGroupID.xy * LIGHT_TILE_SIZE + pixel_in_tile());
  SurfacePoint p;
  vec3 position;
  // Every invocation takes part in the batches' barriers, a surface under it or not.
  bool surface = pixel.x < int(frame.screen.x) && pixel.y < int(frame.screen.y) &&
                 deferred_surface(pixel, p, position);

  // The heaviest weights so far, heaviest first: each weight is carried down the list, the larger
  // of each pair staying (unrolled, the list lives in registers).
  float heaviest[MOST_FILTERED_LIGHTS];
  [[unroll]] for (uint i = 0u; i < MOST_FILTERED_LIGHTS; ++i) heaviest[i] = 0.0;
  for (uint group = 0u; group < LIGHT_GROUP_COUNT; ++group) {
    if (!group_filters(group)) continue;
    uvec2 range = tile_ranges[tile * LIGHT_GROUP_COUNT + group];
    for (uint first = 0u; first < range.y; first += LIGHT_BATCH) {
      uint count = min(range.y - first, LIGHT_BATCH);
      if (gl_LocalInvocationIndex < count) keep_in_batch(gl_LocalInvocationIndex, light_at(tile_lights[range.x + first + gl_LocalInvocationIndex]));
      barrier();
      for (uint j = 0u; surface && j < count; ++j) {
        Light light = batch_light(j);
        Incidence at = light_incidence(light, position, light_type(light, LIGHT_TYPES));
        if (shadow_weight_bound(light, p, at) <= heaviest[FILTERED_LIGHTS - 1u]) continue;
        float carried = shadow_weight(light, p, at);
        if (carried <= heaviest[FILTERED_LIGHTS - 1u]) continue;
        [[unroll]] for (uint i = 0u; i < MOST_FILTERED_LIGHTS; ++i) {
          if (i < FILTERED_LIGHTS) {
            float kept = max(heaviest[i], carried);
            carried = min(heaviest[i], carried);
            heaviest[i] = kept;
          }
        }
      }
      barrier();
    }
  }
  if (!surface) return;
  // A little under the weight, so that the group passes, which work the weight out again in
  // another pipeline (and store it here at half precision), still filter that light.
  float filter_floor = min(0.998 * heaviest[FILTERED_LIGHTS - 1u], MOST_FLOOR);
  vec4 sum = imageLoad(hdr, pixel);
  imageStore(hdr, pixel, vec4(sum.rgb, filter_floor));
}
