// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// 2D shadow maps of casters with a cut-out (shadow_cut_out.glsl): the depth the raster gives,
// nothing where the surface is cut out. After the cut_out variants of shadow_batch.vert and
// shadow_map.vert, which pass the uv and the instance's material on.
#include "shadow_cut_out.glsl"

layout(location = 2) in vec2 in_uv;
layout(location = 3) flat in vec4 in_material;  // scene_instances.glsl's Instance::material

void main() {
  if (shadow_cut_out(in_material, in_uv, uvec2(gl_FragCoord.xy))) discard;
}
