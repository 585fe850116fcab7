// Every light's contribution at a surface point (docs/ALGORITHMS.md section 2), each with
// its own shadow algorithm (shadow_sampling.glsl). The ambient term is not part of the sum: add
// it once per surface point, as blinn_light expects.
#ifndef SG_LIGHT_SHADING_GLSL
#define SG_LIGHT_SHADING_GLSL

#include "lighting.glsl"
#include "light_formulas.glsl"
#include "lights_interface.glsl"
#include "shadow_sampling.glsl"

// The shadow-only debug view (LightingView::shadows): white surfaces under white lights, diffuse
// only, each light's shadow at full density and no shadow color: the algorithm's shade as it
// falls, without textures, colors or highlights in the way.
// constant_id 0 is left to the including shader's own constant.
layout(constant_id = 1) const bool SHADOW_ONLY_VIEW = false;

// One light at world_pos. `reach` folds the light's falloff, spot cone and cylinder lambda
// into its radiance; where it is zero the light adds nothing (not even shadow color) and its
// shadow map is not read. The shadow color term is weighted by lambda as section 2's formula
// has it (lambda is 1 for every light but the cylinder).
//
// `shadow_kind` and `algorithm` are the light's own (light_shadow_kind, info.z); shade_light
// reads them from the record, a pass that shades one light group passes its constants.
vec3 shade_light_as(Light light, SurfacePoint p, vec3 world_pos, uint shadow_kind, uint algorithm) {
  // Only point lights have cube maps: with a constant shadow_kind the other types' branches
  // drop out of a cube group's shader (a CPU driver computes every branch, taken or not).
  uint type = shadow_kind == SHADOW_KIND_CUBE ? LIGHT_POINT : light_type(light);
  vec3 to_light;
  float reach = 1.0;
  float lambda = 1.0;
  if (type == LIGHT_DIRECTIONAL) {
    to_light = -light.direction_type.xyz;
  } else if (type == LIGHT_CYLINDER) {
    // A beam of parallel rays along T: L is -T everywhere, as its orthographic map assumes.
    vec3 axis = light.direction_type.xyz;
    vec3 from_light = world_pos - light.position_range.xyz;
    to_light = -axis;
    lambda = cylinder_lambda(dot(axis, from_light), length(cross(axis, from_light)),
                             light.shape.z, light.shape.w);
    reach = lambda;
  } else {
    vec3 offset = light.position_range.xyz - world_pos;
    float distance = length(offset);
    to_light = offset / max(distance, 1e-6);
    float range = light.position_range.w;
    reach = light.info.y == FALLOFF_GLTF_PUNCTUAL ? falloff_gltf_punctual(distance, range)
                                                  : falloff_linear_window(distance, range);
    if (type == LIGHT_SPOT) {
      reach *= spot_cone(dot(light.direction_type.xyz, -to_light), light.shape.x, light.shape.y);
    }
  }
  if (reach <= 0.0) return vec3(0.0);
  // Facing away from the light, a surface takes nothing from it but shadow color where shadowed:
  // without shadow color no shadow changes the sum, and the shadow lookup, most of a light's cost
  // when many overlap, is skipped.
  vec3 shadow_color = lambda * light.shadow_color_density.rgb;
  if (dot(p.normal, to_light) <= 0.0 && shadow_color == vec3(0.0)) return vec3(0.0);

  float shade =
      light_shadow_as(light, world_pos, p.normal, dot(p.normal, to_light), shadow_kind, algorithm, p.pixel);
  if (SHADOW_ONLY_VIEW) {
    return vec3((1.0 - shade) * light.color_intensity.a * reach * max(dot(p.normal, to_light), 0.0));
  }
  vec3 radiance = light.color_intensity.rgb * light.color_intensity.a * reach;
  return blinn_light(p, to_light, radiance, shade, light.shadow_color_density.a, shadow_color);
}

vec3 shade_light(Light light, SurfacePoint p, vec3 world_pos) {
  return shade_light_as(light, p, world_pos, light_shadow_kind(light), light.info.z);
}

// The sum over lights[0 .. light_count) at world_pos, without ambient.
vec3 shade_lights(SurfacePoint p, vec3 world_pos, uint light_count) {
  vec3 color = vec3(0.0);
  for (uint i = 0u; i < light_count; ++i) {
    color += shade_light(light_at(i), p, world_pos);
  }
  return color;
}

#endif
