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

// The tile's filtering lights, a batch at a time: fetched by each pixel the records cost the
// texture units more than loading them once for the tile (H200, 1920x1080, 2026-12-02: lighting
// 10.33 -> 9.42 ms with 16,384 lights over 20k triangles, 5.56 -> 5.38 with 1,024 on a sixteenth
// of the stress hall; docs/PERFORMANCE.md). A batch holds what a light's bound reads
// (floor_bound), its constants worked out once for the tile, and the record's index for the
// exact weight. Tiles with few lights skip the pass, barriers and all.
const uint LIGHT_BATCH = 256u;  // one light an invocation
shared vec4 batch_position_inverse_range[LIGHT_BATCH];  // xyz position; w 1 / range
shared vec4 batch_direction_outer[LIGHT_BATCH];         // xyz spot direction; w cos(outer)
shared vec4 batch_radiance[LIGHT_BATCH];                // rgb color * intensity; w its luminance
shared vec4 batch_terms[LIGHT_BATCH];  // x 1 / (cos(inner) - cos(outer)); y density * luminance(shadow color);
                                       // z type | falloff << 8; w the record's index

void keep_in_batch(uint slot, uint index) {
  Light light = light_at(index);
  vec3 radiance = light.color_intensity.rgb * light.color_intensity.a;
  batch_position_inverse_range[slot] = vec4(light.position_range.xyz, 1.0 / light.position_range.w);
  batch_direction_outer[slot] = vec4(light.direction_type.xyz, light.shape.y);
  batch_radiance[slot] = vec4(radiance, luminance(radiance));
  batch_terms[slot] = vec4(1.0 / max(light.shape.x - light.shape.y, 1e-6),
                           light.shadow_color_density.a * luminance(light.shadow_color_density.rgb),
                           uintBitsToFloat(light_type(light, LIGHT_TYPES) | light_falloff(light) << 8u),
                           uintBitsToFloat(index));
}

// At least batch light `j`'s shadow_weight at the surface point, `lit_color` the base color
// weighted for luminance: shadow_weight_bound with the light's constants worked out per tile and
// reciprocals for its divisions, a part in 1,000 over for the rounding that differs. Most lights
// a pixel ranks fall below its heaviest few by this alone, and so the pass's time is this
// function's (H100, 1920x1080, 100,000 lights: the pass took 1.39 ms against 1.78 with
// light_incidence and shadow_weight_bound from the record from afar, 3.10 against 4.28 at eye
// height, 2026-12-06). Point and spot lights only, what frames of many lights are made of; for
// the other types a bound that passes, so that their exact weight is worked out.
float floor_bound(uint j, SurfacePoint p, vec3 lit_color, vec3 position) {
  vec4 terms = batch_terms[j];
  uint bits = floatBitsToUint(terms.z);
  uint type = bits & 0xFFu;
  if (type != LIGHT_POINT && type != LIGHT_SPOT) return 1e30;
  vec4 position_inverse_range = batch_position_inverse_range[j];
  vec3 offset = position_inverse_range.xyz - position;
  float distance2 = dot(offset, offset);
  float inverse_distance = inversesqrt(max(distance2, 1e-12));
  vec3 to_light = offset * inverse_distance;
  float inverse_range = position_inverse_range.w;
  bool gltf = (bits >> 8u) == FALLOFF_GLTF_PUNCTUAL;
  float fade = gltf ? gltf_window(distance2 * inverse_range * inverse_range)
                    : max(1.0 - distance2 * inverse_distance * inverse_range, 0.0);
  float reach = gltf ? fade / max(distance2, 1e-4) : fade;
  if (type == LIGHT_SPOT) {
    vec4 direction_outer = batch_direction_outer[j];
    float cone = clamp((dot(direction_outer.xyz, -to_light) - direction_outer.w) * terms.x, 0.0, 1.0);
    reach *= cone;
    fade *= cone;
  }
  vec4 radiance = batch_radiance[j];
  float n_dot_l = dot(p.normal, to_light);
  float lit = n_dot_l > 0.0 ? reach * (n_dot_l * dot(lit_color, radiance.rgb) + p.specular * radiance.w) : 0.0;
  return 1.001 * (lit + fade * terms.y);
}

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

  // The base color weighted for luminance, so that luminance(base_color * radiance) is
  // dot(lit_color, radiance).
  vec3 lit_color = surface ? p.base_color * LUMINANCE_WEIGHTS : vec3(0.0);
  // The heaviest weights so far, heaviest first: each weight is carried down the list, the larger
  // of each pair staying (unrolled, the list lives in registers).
  float heaviest[MOST_FILTERED_LIGHTS];
  [[unroll]] for (uint i = 0u; i < MOST_FILTERED_LIGHTS; ++i) heaviest[i] = 0.0;
  for (uint group = 0u; group < LIGHT_GROUP_COUNT; ++group) {
    if (!group_filters(group)) continue;
    uvec2 range = tile_ranges[tile * LIGHT_GROUP_COUNT + group];
    for (uint first = 0u; first < range.y; first += LIGHT_BATCH) {
      uint count = min(range.y - first, LIGHT_BATCH);
      if (gl_LocalInvocationIndex < count) {
        keep_in_batch(gl_LocalInvocationIndex, tile_lights[range.x + first + gl_LocalInvocationIndex]);
      }
      barrier();
      for (uint j = 0u; surface && j < count; ++j) {
        if (floor_bound(j, p, lit_color, position) <= heaviest[FILTERED_LIGHTS - 1u]) continue;
        // The exact weight from the whole record, as the group passes work it out.
        Light light = light_at(floatBitsToUint(batch_terms[j].w));
        float carried = shadow_weight(light, p, light_incidence(light, position, light_type(light, LIGHT_TYPES)));
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
