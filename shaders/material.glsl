// SPDX-License-Identifier: MIT
// The surface a fragment of an instance shows: base color from the material's factor and
// texture, specular strength and shininess (scene_interface.glsl's Instance). Shared by the
// forward and G-buffer passes, so both light the same surface. Fragment shaders after
// scene.vert only.
#ifndef SG_MATERIAL_GLSL
#define SG_MATERIAL_GLSL

#include "bindings.glsl"
#include "lighting.glsl"
#include "material_textures.glsl"
#include "scene_interface.glsl"

// What scene.vert passes on. The instance's material comes per vertex, flat: read per fragment,
// each of its words was a storage-buffer load, which a CPU driver makes lane by lane (a quarter
// of the G-buffer pass on lavapipe).
layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec4 in_base_color_specular;  // rgb: base color; a: specular strength kS
layout(location = 3) in vec2 in_uv;
// x: Blinn shininess s; y: texture layer or -1; z: base color alpha; w: the mask's cutoff
layout(location = 4) flat in vec4 in_material;
layout(location = 5) flat in uint in_light_layers;

// The base color, factor times texture: rgb and alpha.
vec4 fragment_base_color() {
  vec4 color = vec4(in_base_color_specular.rgb, in_material.z);
  int texture_index = int(in_material.y);
  if (MATERIAL_TEXTURES && texture_index >= 0) {
    color *= texture(base_color_textures, vec3(in_uv, float(texture_index)));
  }
  return color;
}

// Drops the fragment where a masked material's alpha is below its cutoff.
void cut_out(float alpha) {
  if (ALPHA_TEST && alpha < in_material.w) discard;
}

// Back faces (drawn only for double-sided materials) are lit from their side, their normal
// flipped, as glTF defines.
SurfacePoint fragment_surface() {
  vec4 base_color = fragment_base_color();
  cut_out(base_color.a);
  SurfacePoint p;
  p.normal = normalize(gl_FrontFacing ? in_normal : -in_normal);
  p.to_viewer = normalize(frame.camera_position.xyz - in_world_position);
  p.base_color = base_color.rgb;
  p.specular = in_base_color_specular.a;
  // The instance's shininess is negated where it receives no shadow (GpuInstance::material).
  p.shininess = abs(in_material.x);
  p.receives_shadow = in_material.x > 0.0;
  p.light_layers = in_light_layers;
  return p;
}

#endif
