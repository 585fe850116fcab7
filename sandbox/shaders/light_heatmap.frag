// SPDX-License-Identifier: MIT
#version 460
// How many lights each screen tile shades (light culling's lists, light_tiles.comp), as a color
// over the picture: none transparent, then blue through green and yellow to red at
// pass.full_scale lights, and white from eight times that on, where lighting a pixel costs most.
#extension GL_GOOGLE_include_directive : require
#include "light_record.glsl"
#include "light_groups.glsl"
#include "light_tile_layout.glsl"

layout(std430, set = 0, binding = 0) readonly buffer TileRanges { uvec2 ranges[]; };  // per tile, group

layout(push_constant) uniform HeatMap {
  uint tiles_across;
  float full_scale;       // lights at which the ramp reaches red
  vec2 scene_per_frame;   // scene pixels per frame pixel (the frame's render scale)
} pass;

layout(location = 0) out vec4 out_color;

void main() {
  uvec2 tile = uvec2(gl_FragCoord.xy * pass.scene_per_frame) / LIGHT_TILE_SIZE;
  uint first = (tile.y * pass.tiles_across + tile.x) * LIGHT_GROUP_COUNT;
  uint lights = 0u;
  for (uint g = 0u; g < LIGHT_GROUP_COUNT; ++g) lights += ranges[first + g].y;
  if (lights == 0u) discard;
  if (float(lights) >= 8.0 * pass.full_scale) {
    out_color = vec4(1.0, 1.0, 1.0, 0.6);
    return;
  }
  float t = clamp(float(lights) / pass.full_scale, 0.0, 1.0);
  vec3 ramp = t < 0.5 ? mix(vec3(0.0, 0.2, 1.0), vec3(0.0, 1.0, 0.2), t * 2.0)
                      : mix(vec3(1.0, 1.0, 0.0), vec3(1.0, 0.0, 0.0), t * 2.0 - 1.0);
  out_color = vec4(ramp, 0.45);
}
