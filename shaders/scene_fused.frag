#version 460
#extension GL_GOOGLE_include_directive : require
// Forward lighting and tone mapping in one pass, for frames of a few lights: every light at
// every pixel (no light lists), with only the shadow code of the light groups the frame has
// (GROUPS_PRESENT, bit g for group g, a specialization constant), the picture written straight
// into the frame. On a CPU driver every full-screen pass costs milliseconds, and this path has
// two: the depth prepass and this one (docs/PERFORMANCE.md).
#include "light_shading.glsl"
#include "material.glsl"
#include "tone_map.glsl"

layout(constant_id = 0) const uint GROUPS_PRESENT = 0x7FFu;

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in uint in_instance;
layout(location = 3) in vec2 in_uv;

layout(location = 0) out vec4 out_color;

// `light` of group `light_group_index`, shaded if that is `group`; called with literal groups so
// that each call's shadow code is resolved at compile time, and absent groups compile to nothing.
vec3 shade_if_in(uint group, uint light_group_index, Light light, SurfacePoint p) {
  if ((GROUPS_PRESENT & (1u << group)) == 0u || light_group_index != group) return vec3(0.0);
  return shade_light_as(light, p, in_world_position, group_shadow_kind(group), group_algorithm(group));
}

void main() {
  SurfacePoint p = instance_surface(in_instance, in_world_position, in_normal, in_uv);
  vec3 color = frame.camera_position.w * p.base_color;
  for (uint i = 0u; i < frame.counts.x; ++i) {
    Light light = light_at(i);
    uint g = light_group(light_shadow_kind(light), light.info.z);
    color += shade_if_in(0u, g, light, p);
    color += shade_if_in(1u, g, light, p);
    color += shade_if_in(2u, g, light, p);
    color += shade_if_in(3u, g, light, p);
    color += shade_if_in(4u, g, light, p);
    color += shade_if_in(5u, g, light, p);
    color += shade_if_in(6u, g, light, p);
    color += shade_if_in(7u, g, light, p);
    color += shade_if_in(8u, g, light, p);
    color += shade_if_in(9u, g, light, p);
    color += shade_if_in(10u, g, light, p);
  }
  out_color = vec4(tone_map(color, uintBitsToFloat(frame.counts.z)), 1.0);  // the sRGB frame encodes
}
