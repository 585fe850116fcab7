// SPDX-License-Identifier: MIT
// Exposure and tone mapping of the lit sum (docs/ALGORITHMS.md section 5) into displayable
// [0, 1]. Also compiled as C++ (systems/tone_map.cpp) for tests: keep to what both languages
// read alike.
#ifndef SG_TONE_MAP_GLSL
#define SG_TONE_MAP_GLSL

// Below TONE_KNEE the curve is the identity: scenes lit within range look exactly as the
// lighting model computes them. Above it the brightest channel is compressed smoothly towards 1
// (continuous in value and slope at the knee), and the color scaled with it, which keeps its
// hue where a per-channel clamp would turn bright colors white or yellow.
const float TONE_KNEE = 0.8f;

float compress_highlight(float x) {
  if (x <= TONE_KNEE) return x;
  float room = 1.0f - TONE_KNEE;
  return TONE_KNEE + room * (1.0f - exp(-(x - TONE_KNEE) / room));
}

vec3 tone_map(vec3 linear_color, float exposure) {
  vec3 c = max(linear_color * exposure, vec3(0.0f));
  float peak = max(c.x, max(c.y, c.z));
  if (peak <= TONE_KNEE) return c;
  return c * (compress_highlight(peak) / peak);
}

#endif
