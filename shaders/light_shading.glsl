// SPDX-License-Identifier: MIT
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

// Where `light` meets world_pos: the unit direction to it; `reach`, its falloff, spot cone and
// cylinder lambda folded into one factor of its radiance (zero: the light adds nothing there, not
// even shadow color); and `fade`, what of that weights the shadow color term: the same cone and
// lambda, and the falloff's range window without the inverse square (gltf_punctual), so that the
// shadow color fades out where the light does, at its cone's rim and at its range.
struct Incidence {
  vec3 to_light;
  float reach;
  float fade;
};

// `type` is the light's own (light_type), or a constant where the caller knows it.
Incidence light_incidence(Light light, vec3 world_pos, uint type) {
  Incidence at;
  at.reach = 1.0;
  at.fade = 1.0;
  if (type == LIGHT_DIRECTIONAL) {
    at.to_light = -light.direction_type.xyz;
  } else if (type == LIGHT_CYLINDER) {
    // A beam of parallel rays along T: L is -T everywhere, as its orthographic map assumes.
    vec3 axis = light.direction_type.xyz;
    vec3 from_light = world_pos - light.position_range.xyz;
    at.to_light = -axis;
    at.reach = cylinder_lambda(dot(axis, from_light), length(cross(axis, from_light)),
                               light.shape.z, light.shape.w);
    at.fade = at.reach;
  } else {
    vec3 offset = light.position_range.xyz - world_pos;
    float distance = length(offset);
    at.to_light = offset / max(distance, 1e-6);
    float range = light.position_range.w;
    bool gltf = light_falloff(light) == FALLOFF_GLTF_PUNCTUAL;
    at.fade = gltf ? gltf_range_window(distance, range) : falloff_linear_window(distance, range);
    at.reach = gltf ? falloff_gltf_punctual(distance, range) : at.fade;
    if (type == LIGHT_SPOT) {
      float cone = spot_cone(dot(light.direction_type.xyz, -at.to_light), light.shape.x, light.shape.y);
      at.reach *= cone;
      at.fade *= cone;
    }
  }
  return at;
}

vec3 radiance_at(Light light, Incidence at) { return light.color_intensity.rgb * light.color_intensity.a * at.reach; }
vec3 shadow_color_at(Light light, Incidence at) { return at.fade * light.shadow_color_density.rgb; }

// Whether no shadow of `light` can change the sum at the surface point: out of the light's reach,
// on none of the layers it lights, or facing away from it (it takes nothing from the light)
// without shadow color.
bool unaffected(Light light, SurfacePoint p, Incidence at) {
  return at.reach <= 0.0 || !lights_layers(light, p.light_layers) ||
         (dot(p.normal, at.to_light) <= 0.0 && shadow_color_at(light, at) == vec3(0.0));
}

// How much `light`'s shadow can change the pixel: the luminance of all it adds unshadowed plus
// that of its shadow color term, the most that any shade in [0, 1] can move the sum; zero where
// it is unaffected or the surface receives no shadow.
float shadow_weight(Light light, SurfacePoint p, Incidence at) {
  if (unaffected(light, p, at) || !p.receives_shadow) return 0.0;
  vec3 shadow_color = shadow_color_at(light, at);
  float density = light.shadow_color_density.a;
  return luminance(blinn_light(p, at.to_light, radiance_at(light, at), 0.0, density, shadow_color)) +
         density * luminance(shadow_color);
}

// At least shadow_weight, without its highlight's shape: the specular lobe (at most 1) and the
// half vector's normalization are what the weight costs beyond the incidence, and a pixel
// ranking hundreds of lights finds most of them lighter than its heaviest few by this bound
// alone. A part in 10^4 over, for the two sums' rounding.
float shadow_weight_bound(Light light, SurfacePoint p, Incidence at) {
  vec3 radiance = radiance_at(light, at);
  float n_dot_l = dot(p.normal, at.to_light);
  float lit = n_dot_l > 0.0 ? luminance(p.base_color * radiance) * n_dot_l + p.specular * luminance(radiance) : 0.0;
  float density = light.shadow_color_density.a;
  return 1.0001 * (lit + density * luminance(shadow_color_at(light, at)));
}

// Ranked filtering (shade_light_as): whether `light` runs its own kernel at a pixel whose filter
// floor is `filter_floor`, its shadow weighing at least that (0: every light filters). Most lights
// fall below the floor by the bound alone, without the weight's highlight.
bool runs_own_filter(Light light, SurfacePoint p, Incidence at, float filter_floor) {
  return filter_floor <= 0.0 ||
         (shadow_weight_bound(light, p, at) >= filter_floor && shadow_weight(light, p, at) >= filter_floor);
}

// One light at world_pos, with its contact shadow where the including pass reads the depth
// buffer (contact_shadows.glsl, included first). `shadow_kind` and `algorithm` are the light's
// own (light_shadow_kind, info.z), `types` light types that hold its own (LIGHT_TYPES' bits);
// shade_light reads them from the record, a pass that shades light groups passes its constants.
//
// Ranked filtering: a light whose shadow_weight at the pixel is below `filter_floor` takes the
// hard test instead of its own kernel (0: every light filters). The deferred lighting sets the
// floor at each pixel's few heaviest lights (lighting_filter_floor.comp): where many lights
// overlap, what costs is their kernels' taps, and a light that adds little to the pixel changes
// it by less than its weight times the filters' difference, which is zero outside penumbrae.
vec3 shade_light_as(Light light, SurfacePoint p, vec3 world_pos, uint shadow_kind, uint algorithm,
                    float filter_floor, uint types) {
  // Only point lights have cube maps: with a constant shadow_kind the other types' branches
  // drop out of a cube group's shader (a CPU driver computes every branch, taken or not).
  uint type = shadow_kind == SHADOW_KIND_CUBE ? LIGHT_POINT : light_type(light, types);
  Incidence at = light_incidence(light, world_pos, type);
  // There the light adds nothing whatever its shadow, and the shadow lookup, most of a light's
  // cost when many overlap, is skipped.
  if (unaffected(light, p, at)) return vec3(0.0);
  float n_dot_l = dot(p.normal, at.to_light);

  // Two calls, each with a constant algorithm, so that each keeps only its own kernel's code. A
  // surface that receives no shadow is lit. A hard light takes the hard test either way, so its
  // rank is worked out only where its contact shadow reads it: in the hard groups' passes the
  // unread ranking took 0.26-0.30 ms of 0.64 and 2.2 at eye height (H100, 1920x1080, 100,000
  // lights, 2026-12-06).
  bool ranked = algorithm != SHADOW_HARD;
#ifdef SG_CONTACT_SHADOWS
  ranked = ranked || CONTACT_SHADOWS;
#endif
  bool filtered = SHADOW_ONLY_VIEW || (ranked && runs_own_filter(light, p, at, filter_floor));
  float shade = !p.receives_shadow ? 0.0
                : filtered ? light_shadow_as(light, world_pos, p.normal, n_dot_l, shadow_kind, algorithm, types)
                           : light_shadow_as(light, world_pos, p.normal, n_dot_l, shadow_kind, SHADOW_HARD, types);
#ifdef SG_CONTACT_SHADOWS
  // The light's contact shadow over its map's, where the pass reads the depth buffer: for the
  // lights that run their own filter, which ranked filtering holds to a pixel's heaviest few.
  if (CONTACT_SHADOWS && filtered && p.receives_shadow && n_dot_l > 0.0 && shade < 1.0 &&
      light.direction_type.w > 0.0) {
    shade = max(shade, contact_shade(light, world_pos, p.normal, at.to_light, type));
  }
#endif
  if (SHADOW_ONLY_VIEW) {
    return vec3((1.0 - shade) * light.color_intensity.a * at.reach * max(n_dot_l, 0.0));
  }
  return blinn_light(p, at.to_light, radiance_at(light, at), shade, light.shadow_color_density.a,
                     shadow_color_at(light, at));
}

vec3 shade_light(Light light, SurfacePoint p, vec3 world_pos) {
  return shade_light_as(light, p, world_pos, light_shadow_kind(light), light_algorithm(light), 0.0, LIGHT_TYPES);
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
