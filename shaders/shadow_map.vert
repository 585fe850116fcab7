#version 460
#extension GL_GOOGLE_include_directive : require
// Shadow-map depth pass: casters' positions into one light view's clip space. Instances through
// the view's caster list (shadow_casters.glsl) into Instances (scene_interface.glsl). Push
// constants: the FrameConstants block of scene_interface.glsl, of which only view_projection (bytes 0..63) is
// read: the light view's (LightView::view_projection() or one CubeViews face). 2D maps need no
// fragment shader; cube faces add shadow_cube.frag, which reads the world position.
#include "scene_interface.glsl"
#include "shadow_casters.glsl"

layout(location = 0) in vec3 in_position;

layout(location = 0) out vec3 out_world_position;

void main() {
  vec4 world = instances[view_instances[gl_InstanceIndex]].model * vec4(in_position, 1.0);
  out_world_position = world.xyz;
  gl_Position = frame.view_projection * world;
}
