#version 460
#extension GL_GOOGLE_include_directive : require
// The lighting pass: ambient plus every light of the frame, each with its own shadow algorithm
// (ALGORITHMS.md sections 2 and 4).
#include "scene_interface.glsl"
#include "light_shading.glsl"

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in uint in_instance;
layout(location = 3) in vec2 in_uv;

// Every material texture of the scene, one per layer (systems/gpu_textures.h).
layout(set = 0, binding = material_textures_binding) uniform sampler2DArray base_color_textures;

layout(location = 0) out vec4 out_color;

void main() {
  Instance inst = instances[in_instance];
  SurfacePoint p;
  p.normal = normalize(in_normal);
  p.to_viewer = normalize(frame.camera_position.xyz - in_world_position);
  p.base_color = inst.base_color_specular.rgb;
  int texture_index = int(inst.material.y);
  if (texture_index >= 0) {
    p.base_color *= texture(base_color_textures, vec3(in_uv, float(texture_index))).rgb;
  }
  p.specular = inst.base_color_specular.a;
  p.shininess = inst.material.x;

  vec3 color = frame.camera_position.w * p.base_color;
  color += shade_lights(p, in_world_position, frame.counts.x);
  out_color = vec4(color, 1.0);  // linear; the sRGB target encodes
}
