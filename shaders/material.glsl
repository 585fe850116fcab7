// The surface a fragment of an instance shows: base colour from the material's factor and
// texture, specular strength and shininess (scene_interface.glsl's Instance). Shared by the
// forward and G-buffer passes, so both light the same surface. Fragment shaders after
// scene.vert only.
#ifndef SG_MATERIAL_GLSL
#define SG_MATERIAL_GLSL

#include "bindings.glsl"
#include "lighting.glsl"
#include "scene_interface.glsl"

// Every material texture of the scene, one per layer (systems/gpu_textures.h).
layout(set = 0, binding = material_textures_binding) uniform sampler2DArray base_color_textures;
// False for a scene without images: a CPU driver samples the texture for every fragment
// whatever the branch says (it runs both sides of every branch), so the sampling code is left
// out at compile time. constant_id 0 and 1 are the including shaders' own.
layout(constant_id = 2) const bool MATERIAL_TEXTURES = true;

// What scene.vert passes on. The instance's material comes per vertex, flat: read per fragment,
// each of its words was a storage-buffer load, which a CPU driver makes lane by lane (a quarter
// of the G-buffer pass on lavapipe).
layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec4 in_base_color_specular;  // rgb: base colour; a: specular strength kS
layout(location = 3) in vec2 in_uv;
layout(location = 4) flat in vec2 in_shininess_texture;  // x: Blinn shininess s; y: texture layer or -1

SurfacePoint fragment_surface() {
  SurfacePoint p;
  p.normal = normalize(in_normal);
  p.to_viewer = normalize(frame.camera_position.xyz - in_world_position);
  p.base_color = in_base_color_specular.rgb;
  int texture_index = int(in_shininess_texture.y);
  if (MATERIAL_TEXTURES && texture_index >= 0) {
    p.base_color *= texture(base_color_textures, vec3(in_uv, float(texture_index))).rgb;
  }
  p.specular = in_base_color_specular.a;
  p.shininess = in_shininess_texture.x;
  p.pixel = uvec2(gl_FragCoord.xy);
  return p;
}

#endif
