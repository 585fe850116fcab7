// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The tiled forward path's depth prepass: scene.vert's position and nothing else, computed the
// same way, so the forward pass's depth test finds the depths written here.
#include "scene_interface.glsl"

layout(location = 0) in vec3 in_position;

void main() {
  vec4 world = instances[gl_InstanceIndex].model * vec4(in_position, 1.0);
  gl_Position = frame.view_projection * world;
}
