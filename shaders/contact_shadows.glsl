// SPDX-License-Identifier: MIT
// Contact shadows (docs/ALGORITHMS.md section 4.8): from a surface point, a short ray toward the
// light marched through the camera's depth buffer; a step that lands behind a drawn surface, by
// less than the ray's length, is in that surface's shadow. They catch the small gaps under and
// beside casters (a foot on a floor, a crate's edge) that a map of a few dozen texels misses, and
// only those: what the camera does not see casts no contact shadow.
//
// For passes that read the depth buffer and shade from tiled_lighting_frame.glsl's constants
// (tiled deferred lighting). Included before light_shading.glsl, it defines SG_CONTACT_SHADOWS,
// and shade_light_as adds a light's contact shadow to its map's where CONTACT_SHADOWS is set.
#ifndef SG_CONTACT_SHADOWS_GLSL
#define SG_CONTACT_SHADOWS_GLSL
#define SG_CONTACT_SHADOWS

#include "bindings.glsl"
#include "camera_depth.glsl"
#include "light_formulas.glsl"
#include "light_record.glsl"
#include "tiled_lighting_frame.glsl"

layout(set = 0, binding = scene_depth_binding) uniform sampler2D scene_depth;

// constant_id 7 (0 to 5 are tiled_lighting.glsl's, 6 lighting_filter_floor.comp's): the pass's
// lights include one with contact shadows (ShadowSettings::contact_length > 0).
layout(constant_id = 7) const bool CONTACT_SHADOWS = false;
const uint CONTACT_STEPS = 12u;

// The invocation's pixel and the camera's world -> clip matrix, set by begin_contact_shadows: the
// frame's constants hold only the inverse (128 bytes of push constants hold no second matrix),
// inverted once per invocation, not per step.
ivec2 contact_pixel;
mat4 contact_view_projection;

void begin_contact_shadows(ivec2 pixel) {
  contact_pixel = pixel;
  if (CONTACT_SHADOWS) contact_view_projection = inverse(frame.inverse_view_projection);
}

// 1 where a drawn surface lies between `position` (on a surface of unit normal `normal`) and the
// light within its contact length, 0 otherwise. `to_light` is the unit direction to the light,
// `type` the light's (LIGHT_*).
float contact_shade(Light light, vec3 position, vec3 normal, vec3 to_light, uint type) {
  float reach = light.direction_type.w;
  if (type == LIGHT_POINT || type == LIGHT_SPOT) reach = min(reach, distance(light.position_range.xyz, position));
  if (reach <= 0.0) return 0.0;
  // The depth buffer gives positions back to about a thousandth of their distance: the ray starts
  // that far off the surface, and a surface nearer than that is the receiver itself.
  vec3 eye = frame.camera_position.xyz;
  float tolerance = 0.002 * distance(eye, position);
  vec3 start = position + normal * tolerance;
  float step_length = reach / float(CONTACT_STEPS);
  // Each pixel's steps start at a random fraction of a step: banding turns into fine noise.
  float offset = cell_random(uvec2(contact_pixel), 7u).x;
  for (uint i = 0u; i < CONTACT_STEPS; ++i) {
    vec3 point = start + to_light * (step_length * (float(i) + offset));
    vec4 clip = contact_view_projection * vec4(point, 1.0);
    if (clip.w <= 0.0) break;
    vec3 ndc = clip.xyz / clip.w;
    if (any(greaterThan(abs(ndc.xy), vec2(1.0)))) break;  // off the screen: nothing known there
    ivec2 texel = min(ivec2((ndc.xy * 0.5 + 0.5) * vec2(frame.screen.xy)), ivec2(frame.screen.xy) - 1);
    float depth = texelFetch(scene_depth, texel, 0).r;
    if (depth <= ndc.z) continue;  // the surface there lies behind the point (depth is reversed)
    vec4 surface = frame.inverse_view_projection * vec4(ndc.xy, depth, 1.0);
    float gap = distance(eye, point) - distance(eye, surface.xyz / surface.w);
    // A surface in front by more than the ray is long is taken to be something else, far in
    // front, not a caster beside the point.
    if (gap > tolerance && gap < reach) return 1.0;
  }
  return 0.0;
}

#endif
