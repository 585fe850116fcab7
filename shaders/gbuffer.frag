#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer of tiled deferred lighting: what lighting_ambient.comp, light_tiles.comp and
// tiled_lighting.comp need of each visible surface point.
#include "material.glsl"

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in uint in_instance;
layout(location = 3) in vec2 in_uv;

layout(location = 0) out vec4 out_position;  // xyz: world position, exact (noise hashes its bits); w: shininess
layout(location = 1) out vec4 out_normal;    // xyz: unit normal; w: specular strength kS
layout(location = 2) out vec4 out_albedo;    // rgb: base colour; a: 1 where a surface was drawn

void main() {
  SurfacePoint p = instance_surface(in_instance, in_world_position, in_normal, in_uv);
  out_position = vec4(in_world_position, p.shininess);
  out_normal = vec4(p.normal, p.specular);
  out_albedo = vec4(p.base_color, 1.0);
}
