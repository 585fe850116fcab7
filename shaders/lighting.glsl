// SPDX-License-Identifier: MIT
// The lighting model of docs/ALGORITHMS.md section 2: extended Blinn with shadow density and
// shadow color. `shade` is the light's shadow factor (1 = fully shadowed).
#ifndef SG_LIGHTING_GLSL
#define SG_LIGHTING_GLSL

struct SurfacePoint {
  vec3 normal;      // unit
  vec3 to_viewer;   // unit
  vec3 base_color;
  float specular;   // kS
  float shininess;  // s
  bool receives_shadow;  // false: lit as if no light cast a shadow here (MeshInstance)
  uint light_layers;     // the layers lights see it on (MeshInstance::light_layers)
};

// One light's contribution, without the ambient term (added once per fragment).
// radiance: light color * intensity * attenuation (lambda * A folded in).
vec3 blinn_light(SurfacePoint p, vec3 to_light, vec3 radiance, float shade, float density,
                 vec3 shadow_color) {
  float sh = density * shade;
  vec3 h = normalize(to_light + p.to_viewer);
  float n_dot_l = max(dot(p.normal, to_light), 0.0);
  float n_dot_h = max(dot(p.normal, h), 0.0);
  // Blinn specular only where the surface faces the light.
  float spec = n_dot_l > 0.0 ? pow(n_dot_h, p.shininess) : 0.0;
  return (1.0 - sh) * p.base_color * radiance * n_dot_l + sh * shadow_color +
         (1.0 - shade) * p.specular * radiance * spec;
}

#endif
