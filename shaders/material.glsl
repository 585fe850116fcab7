// The surface a fragment of an instance shows: base colour from the material's factor and
// texture, specular strength and shininess (scene_interface.glsl's Instance). Shared by the
// forward and G-buffer passes, so both light the same surface. Fragment shaders only.
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

SurfacePoint instance_surface(uint instance, vec3 world_position, vec3 normal, vec2 uv) {
  Instance inst = instances[instance];
  SurfacePoint p;
  p.normal = normalize(normal);
  p.to_viewer = normalize(frame.camera_position.xyz - world_position);
  p.base_color = inst.base_color_specular.rgb;
  int texture_index = int(inst.material.y);
  if (MATERIAL_TEXTURES && texture_index >= 0) {
    p.base_color *= texture(base_color_textures, vec3(uv, float(texture_index))).rgb;
  }
  p.specular = inst.base_color_specular.a;
  p.shininess = inst.material.x;
  p.pixel = uvec2(gl_FragCoord.xy);
  return p;
}

#endif
