// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The spot light with 3 x 3 PCF: nine depth fetches around the point's map texel, each compared.
#include "plain_shading.glsl"

layout(set = 0, binding = 0) uniform sampler2D shadow_map;

layout(location = 0) out vec4 out_color;

const float BIAS = 0.0005;

void main() {
  vec4 clip = frame.light * vec4(in_position, 1.0);
  vec3 map = clip.xyz / clip.w;
  vec2 uv = map.xy * 0.5 + 0.5;
  vec2 texel = 1.0 / vec2(textureSize(shadow_map, 0));
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y) {
    for (int x = -1; x <= 1; ++x) {
      lit += map.z - BIAS <= texture(shadow_map, uv + vec2(x, y) * texel).r ? 1.0 : 0.0;
    }
  }
  vec3 to_light = normalize(frame.light_position_range.xyz - in_position);
  float cone = spot_cone(dot(-to_light, frame.light_direction.xyz), frame.light_color.w, frame.light_direction.w);
  out_color = shaded(cone, 1.0 - lit / 9.0);
}
