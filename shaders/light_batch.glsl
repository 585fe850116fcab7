// SPDX-License-Identifier: MIT
// A tile's lights in shared memory, a batch at a time, holding what an unshadowed light's shading
// reads of each (light_shading.glsl): every pixel of a tile reads every light of the tile, and
// loaded once for the tile the records cost less than once a pixel, through the texture units or
// a warp's storage loads (docs/PERFORMANCE.md: the unshadowed lights' pass). The including shader
// defines LIGHT_BATCH, the lights a batch holds, before including this.
#ifndef SG_LIGHT_BATCH_GLSL
#define SG_LIGHT_BATCH_GLSL

#include "light_record.glsl"

shared vec4 batch_position_range[LIGHT_BATCH];
shared vec4 batch_direction_type[LIGHT_BATCH];
shared vec4 batch_color_intensity[LIGHT_BATCH];
shared vec4 batch_shape[LIGHT_BATCH];
shared vec4 batch_shadow_color_density[LIGHT_BATCH];
shared uvec2 batch_type_falloff[LIGHT_BATCH];

void keep_in_batch(uint slot, Light light) {
  batch_position_range[slot] = light.position_range;
  batch_direction_type[slot] = light.direction_type;
  batch_color_intensity[slot] = light.color_intensity;
  batch_shape[slot] = light.shape;
  batch_shadow_color_density[slot] = light.shadow_color_density;
  batch_type_falloff[slot] = light.info.xy;
}

// Slot `slot`'s light, the members the batch does not hold left zero (no shadow map).
Light batch_light(uint slot) {
  Light light;
  light.position_range = batch_position_range[slot];
  light.direction_type = batch_direction_type[slot];
  light.color_intensity = batch_color_intensity[slot];
  light.shape = batch_shape[slot];
  light.shadow_color_density = batch_shadow_color_density[slot];
  light.info = uvec4(batch_type_falloff[slot], 0u, NO_SHADOW_MAP);
  light.shadow_bias = vec4(0.0);
  light.shadow_rect = vec4(0.0);
  light.shadow_depth = vec4(0.0);
  light.shadow_matrix = mat4(0.0);
  return light;
}

#endif
