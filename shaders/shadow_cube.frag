// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant cut_out SHADOW_CUT_OUT
// Point-light cube faces store distance / far instead of the projection's depth, so that
// receivers compare length(fragWorld - P) / far in any direction (docs/ALGORITHMS.md section 3).
// Clear the faces to 1 (nothing within range) and depth-test LESS. Distances beyond far (the
// face corners reach past it) store 1, which reads as "nothing within range" too. The light's
// position and far plane come from the vertex stage (shadow_map.vert, shadow_cube_layered.vert,
// shadow_batch.vert), flat. The cut_out variant, after those shaders' cut_out variants, leaves
// out what a caster's cut-out removes (shadow_cut_out.glsl).
#ifdef SHADOW_CUT_OUT
#include "shadow_cut_out.glsl"
layout(location = 2) in vec2 in_uv;
layout(location = 3) flat in vec4 in_material;  // scene_instances.glsl's Instance::material
#endif

layout(location = 0) in vec3 in_world_position;
layout(location = 1) flat in vec4 in_light_position_far;  // xyz: light position, w: far plane (its range)

void main() {
#ifdef SHADOW_CUT_OUT
  if (shadow_cut_out(in_material, in_uv, uvec2(gl_FragCoord.xy))) discard;
#endif
  float distance = length(in_world_position - in_light_position_far.xyz);
  gl_FragDepth = min(distance / in_light_position_far.w, 1.0);
}
