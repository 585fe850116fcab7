// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant cut_out SHADOW_CUT_OUT
// Shadow-map depth pass of one view, one pass per view (the per-light baseline; shadow_batch.vert
// draws every view at once): casters' positions into the light view's clip space, the pass's
// viewport being the view's atlas tile. Instances through the view's caster list
// (shadow_casters.glsl) into Instances (scene_instances.glsl). Push constants:
// shadow_pass_constants.glsl, light_position_far handed to shadow_cube.frag for cube faces. 2D
// maps need no fragment shader.
#include "shadow_pass_constants.glsl"
#include "scene_instances.glsl"
#include "shadow_casters.glsl"

layout(location = 0) in vec3 in_position;

layout(location = 0) out vec3 out_world_position;
layout(location = 1) flat out vec4 out_light_position_far;

#ifdef SHADOW_CUT_OUT  // the uv and the material, for shadow_cut_out.frag and shadow_cube.frag
layout(location = 2) in vec2 in_uv;
layout(location = 2) out vec2 out_uv;
layout(location = 3) flat out vec4 out_material;
#endif

void main() {
  vec4 world = instances[view_instances[gl_InstanceIndex]].model * vec4(in_position, 1.0);
  out_world_position = world.xyz;
  out_light_position_far = pass.light_position_far;
  gl_Position = pass.view_projection * world;
#ifdef SHADOW_CUT_OUT
  out_uv = in_uv;
  out_material = instances[view_instances[gl_InstanceIndex]].material;
#endif
}
