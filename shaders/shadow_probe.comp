// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant storage_records LIGHT_RECORDS_IN_STORAGE
// What the lit frame's shadows were, light by light, for measuring them (tools/reference's
// whole-frame mode; systems/lighting/shadow_probe.h): after the light groups' passes, each pixel
// walks its tile's lights of every group and, for each whose shadow can change the pixel
// (shadow_weight > 0), records the shade the group pass gave it (the same kernel, or the hard
// test below the pixel's filter floor) and that weight. Not part of a normal frame.
#include "tiled_lighting.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = hdr_binding, rgba16f) uniform readonly image2D hdr;

// Set before the dispatch (ShadowProbe::record_start): `capacity` pairs fit; a pair is kept where
// its cell_random draw is below `keep` (1: every pair). The pass counts the pairs it met in
// `wanted` (one atomic a pixel) and those it kept in `kept`, writing the first `capacity` kept:
// pixel index, record index, and packHalf2x16(shade, weight). `listed` counts the (tile, light)
// pairs of the light lists, each tile's by its first pixel.
layout(std430, set = 0, binding = shadow_probe_binding) buffer Probe {
  uint wanted;
  uint kept;
  uint capacity;
  float keep;
  uint listed;
  uint pairs[];
} probe;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= int(frame.screen.x) || pixel.y >= int(frame.screen.y)) return;
  uint tile = (uint(pixel.y) / LIGHT_TILE_SIZE) * frame.screen.z + uint(pixel.x) / LIGHT_TILE_SIZE;
  if (all(equal(uvec2(pixel) % LIGHT_TILE_SIZE, uvec2(0u)))) {
    uint listed = 0u;
    for (uint group = 0u; group < LIGHT_GROUP_COUNT; ++group) listed += tile_ranges[tile * LIGHT_GROUP_COUNT + group].y;
    atomicAdd(probe.listed, listed);
  }
  SurfacePoint p;
  vec3 position;
  if (!deferred_surface(pixel, p, position)) return;
  float filter_floor = RANKED_FILTERING ? imageLoad(hdr, pixel).a : 0.0;
  uint pixel_index = uint(pixel.y) * frame.screen.x + uint(pixel.x);
  uint met = 0u;
  for (uint group = 0u; group < LIGHT_GROUP_COUNT; ++group) {
    uvec2 range = tile_ranges[tile * LIGHT_GROUP_COUNT + group];
    for (uint j = 0u; j < range.y; ++j) {
      uint index = tile_lights[range.x + j];
      Light light = light_at(index);
      Incidence at = light_incidence(light, position, light_type(light, LIGHT_TYPES));
      float weight = shadow_weight(light, p, at);
      if (weight <= 0.0) continue;
      ++met;
      if (probe.keep < 1.0 && cell_random(uvec2(pixel), index).x >= probe.keep) continue;
      // As shade_light_as decides, with the light's own kind and algorithm.
      uint kind = light_shadow_kind(light);
      bool filtered = runs_own_filter(light, p, at, filter_floor);
      float n_dot_l = dot(p.normal, at.to_light);
      float shade = light_shadow_as(light, position, p.normal, n_dot_l, kind,
                                    filtered ? light_algorithm(light) : SHADOW_HARD, LIGHT_TYPES);
      uint slot = atomicAdd(probe.kept, 1u);
      if (slot >= probe.capacity) continue;
      probe.pairs[3u * slot] = pixel_index;
      probe.pairs[3u * slot + 1u] = index;
      probe.pairs[3u * slot + 2u] = packHalf2x16(vec2(shade, weight));
    }
  }
  atomicAdd(probe.wanted, met);
}
