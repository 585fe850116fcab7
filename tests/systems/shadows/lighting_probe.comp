// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// Built, never run: compiles light_shading.glsl (with shadow_sampling.glsl and the light
// resources) the way a lighting shader uses it, and glslang's reflection of this shader
// (glslangValidator -q) gives the std430 layout of `Light` that light_record_layout_test.cpp
// compares with sg::shadows::GpuLight: the layout light_tiles.comp reads from a storage buffer,
// and whose 16-byte texels light_at (lights_interface.glsl) reads from the texel buffer.
#include "light_shading.glsl"

layout(local_size_x = 1) in;

layout(std430, set = 1, binding = 0) writeonly buffer Result { vec4 color; } result;
layout(std430, set = 1, binding = 1) readonly buffer Lights { Light lights[]; };

void main() {
  SurfacePoint p;
  p.normal = vec3(0.0, 1.0, 0.0);
  p.to_viewer = vec3(0.0, 1.0, 0.0);
  p.base_color = vec3(0.5);
  p.specular = 0.5;
  p.shininess = 32.0;
  p.light_layers = 1u;
  result.color = vec4(shade_lights(p, vec3(0.0), uint(lights.length())), 1.0);
}
