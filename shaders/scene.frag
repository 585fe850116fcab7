#version 460
#extension GL_GOOGLE_include_directive : require
#include "scene_interface.glsl"
#include "lighting.glsl"

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in uint in_instance;

layout(location = 0) out vec4 out_color;

void main() {
  Instance inst = instances[in_instance];
  SurfacePoint p;
  p.normal = normalize(in_normal);
  p.to_viewer = normalize(frame.camera_position.xyz - in_world_position);
  p.base_color = inst.base_color_specular.rgb;
  p.specular = inst.base_color_specular.a;
  p.shininess = inst.material.x;

  vec3 to_sun = -frame.sun_direction.xyz;
  vec3 radiance = frame.sun_color.rgb * frame.sun_direction.w;
  vec3 color = frame.sun_color.a * p.base_color;
  color += blinn_light(p, to_sun, radiance, 0.0, 1.0, vec3(0.0));
  out_color = vec4(color, 1.0);  // linear; the sRGB target encodes
}
