// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant transparent TRANSPARENT
// variant groups_1 GROUP_SLOTS=1
// variant groups_2 GROUP_SLOTS=2
// variant groups_3 GROUP_SLOTS=3
// variant groups_4 GROUP_SLOTS=4
// variant transparent_groups_1 TRANSPARENT GROUP_SLOTS=1
// variant transparent_groups_2 TRANSPARENT GROUP_SLOTS=2
// variant transparent_groups_3 TRANSPARENT GROUP_SLOTS=3
// variant transparent_groups_4 TRANSPARENT GROUP_SLOTS=4
// Forward lighting and tone mapping in one pass, for frames of a few lights: every light at
// every pixel (no light lists), each with its own group's shadow code, the shader holding only
// the code of the light groups the frame has (GROUPS_PRESENT, bit g for group g, a
// specialization constant), the picture written straight into the frame. On a CPU driver every
// full-screen pass costs milliseconds, and this path has two: the depth prepass and this one
// (docs/PERFORMANCE.md). The groups_N variants call the shading for the frame's N groups alone
// (group_slots.glsl), which their pipelines build in a fraction of the time.
//
// The transparent variant (systems/lighting/transparent_pass.h) gives the surface's alpha for blending,
// its color tone-mapped only where frame.counts.w is 1: into the fused path's frame, or as a
// lit sum after the every-light path.
#include "group_slots.glsl"
#include "light_shading.glsl"
#include "material.glsl"
#include "tone_map.glsl"

layout(constant_id = 0) const uint GROUPS_PRESENT = 0x7FFu;
// constant_id 1 to 3 are light_shading.glsl's, material.glsl's and lights_interface.glsl's. 4: bit g
// set where group g has exactly one light, which is then shaded with no loop and no look at the
// record after it. 5: each group's light types (group_light_types), so that a group holds only its
// own lights' code, not that of every type the frame has.
layout(constant_id = 4) const uint GROUPS_SINGLE = 0u;
layout(constant_id = 5) const uint GROUP_TYPES = 0x3FFFFFFFu;

layout(location = 0) out vec4 out_color;

// The light group of record `index` (at most the last), from its info alone.
uint group_at(uint index) {
  Light light;  // what light_shadow_kind and light_algorithm read
  light.info = light_info_at(min(index, frame.counts.x - 1u));
  return light_group(light_shadow_kind(light), light_algorithm(light));
}

// The lights of `group`, which are the records from `next` on: the records are sorted by group
// (systems/shadows/frame_lights.h) and the groups are visited in order. Called with literal
// groups, so each call's shadow code is resolved at compile time and absent groups compile to
// nothing. A present group has at least one light, and a do-while runs its body exactly that
// often on a CPU driver too (a for loop runs one more, masked, pass over the body), so a pixel
// pays each light's own algorithm once, not every present group's code for every light.
//
// Where a group of several ends is read from the next record's info alone: fetching the whole
// next record ahead, as the loop once did, cost a one-light group 13 texel fetches a pixel for
// nothing.
vec3 shade_group(uint group, inout uint next, SurfacePoint p) {
  vec3 color = vec3(0.0);
  if ((GROUPS_PRESENT & (1u << group)) == 0u) return color;
  uint kind = group_shadow_kind(group);
  uint algorithm = group_algorithm(group);
  uint types = group_light_types(GROUP_TYPES, group);
  // One call of the shading, which the compiler inlines whole: a second, for single lights, made
  // the pipelines take twice as long to build.
  bool single = (GROUPS_SINGLE & (1u << group)) != 0u;
  do {
    color += shade_light_as(light_at(next), p, in_world_position, kind, algorithm, 0.0, types);
    ++next;
  } while (!single && next < frame.counts.x && group_at(next) == group);
  return color;
}

void main() {
  SurfacePoint p = fragment_surface();
  vec3 color = frame.ambient.rgb * p.base_color;
  uint next = 0u;
  // A call a group slot (group_slots.glsl), each with a group that is a constant, so that its shadow
  // code is resolved when the pipeline is built.
#define SHADE_SLOT(slot) color += shade_group(slot_group(slot), next, p);
  FOR_EACH_GROUP_SLOT(SHADE_SLOT)
#ifdef TRANSPARENT
  if (frame.counts.w == 1u) color = tone_map(color, uintBitsToFloat(frame.counts.z));
  out_color = vec4(color, fragment_base_color().a);
#else
  out_color = vec4(tone_map(color, uintBitsToFloat(frame.counts.z)), 1.0);  // the sRGB frame encodes
#endif
}
