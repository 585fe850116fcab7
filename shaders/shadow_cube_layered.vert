// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant cut_out SHADOW_CUT_OUT
// All six faces of one point light's cube in one draw (the single-pass option of docs/ALGORITHMS.md
// section 3), with shadow_cube.frag, in the per-light baseline. Draw the casters as for one face
// but with instanceCount x 6 (firstInstance unchanged): copy k of a draw renders caster
// gl_BaseInstance + k / 6 of the view's list (shadow_casters.glsl) into face k % 6. The faces
// are tiles of one atlas layer, the pass's attachment: each face's clip xy is moved into its
// tile and clipped to the face's frustum sides, as shadow_batch.vert does for every view.
//
// Device features: shaderClipDistance, shaderDrawParameters (gl_BaseInstance).
//
// Resources: Instances (scene_instances.glsl), the view's casters (shadow_casters.glsl) and the
// cube's faces (one CubeFaces slice per point light of one buffer, bound with a dynamic offset).
// Push constants as for shadow_map.vert (shadow_pass_constants.glsl).
#include "shadow_pass_constants.glsl"
#include "scene_instances.glsl"
#include "shadow_casters.glsl"

layout(std140, set = 0, binding = cube_faces_binding) uniform CubeFaces {
  mat4 face_view_projection[6];  // +X, -X, +Y, -Y, +Z, -Z
  vec4 face_tile[6];             // clip xy -> the layer's: xy scale, zw offset (times w)
} cube;

layout(location = 0) in vec3 in_position;

layout(location = 0) out vec3 out_world_position;
layout(location = 1) flat out vec4 out_light_position_far;

#ifdef SHADOW_CUT_OUT  // the uv and the material, for shadow_cut_out.frag and shadow_cube.frag
layout(location = 2) in vec2 in_uv;
layout(location = 2) out vec2 out_uv;
layout(location = 3) flat out vec4 out_material;
#endif

out float gl_ClipDistance[4];

void main() {
  int copy = gl_InstanceIndex - gl_BaseInstance;
  int face = copy % 6;
  vec4 world = instances[view_instances[gl_BaseInstance + copy / 6]].model * vec4(in_position, 1.0);
  vec4 clip = cube.face_view_projection[face] * world;
  vec4 tile = cube.face_tile[face];
  gl_ClipDistance[0] = clip.w + clip.x;
  gl_ClipDistance[1] = clip.w - clip.x;
  gl_ClipDistance[2] = clip.w + clip.y;
  gl_ClipDistance[3] = clip.w - clip.y;
  gl_Position = vec4(clip.xy * tile.xy + tile.zw * clip.w, clip.zw);
  out_world_position = world.xyz;
  out_light_position_far = pass.light_position_far;
#ifdef SHADOW_CUT_OUT
  out_uv = in_uv;
  out_material = instances[view_instances[gl_BaseInstance + copy / 6]].material;
#endif
}
