// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// variant cut_out SHADOW_CUT_OUT
#extension GL_ARB_shader_viewport_layer_array : require
// Every shadow view of the frame in one draw per (view kind, mesh): instance k of the draw is
// the sorted pair (instance, view) at gl_InstanceIndex (shadow_scatter.comp). The caster is
// projected by its view and moved into the view's atlas tile (ShadowView::tile) on atlas layer
// info.x; the clip distances are the view's own frustum sides, so nothing spills into a
// neighbouring tile. 2D views need no fragment shader; cube faces add shadow_cube.frag.
//
// Device features: shaderOutputLayer (gl_Layer from a vertex shader), shaderClipDistance.
#include "scene_instances.glsl"
#include "shadow_views.glsl"

layout(std430, set = 0, binding = view_instances_binding) readonly buffer Sorted { uvec2 sorted_pairs[]; };

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
  uvec2 pair = sorted_pairs[gl_InstanceIndex];
  vec4 world = instances[pair.x].model * vec4(in_position, 1.0);
  vec4 clip = views[pair.y].view_projection * world;
  vec4 tile = views[pair.y].tile;
  gl_ClipDistance[0] = clip.w + clip.x;
  gl_ClipDistance[1] = clip.w - clip.x;
  gl_ClipDistance[2] = clip.w + clip.y;
  gl_ClipDistance[3] = clip.w - clip.y;
  gl_Position = vec4(clip.xy * tile.xy + tile.zw * clip.w, clip.zw);
  gl_Layer = int(views[pair.y].info.x);
  out_world_position = world.xyz;
  out_light_position_far = views[pair.y].position_far;
#ifdef SHADOW_CUT_OUT
  out_uv = in_uv;
  out_material = instances[pair.x].material;
#endif
}
