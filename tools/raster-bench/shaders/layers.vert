// SPDX-License-Identifier: MIT
#version 460
// Depth-only benchmark geometry: positions in NDC from the vertex buffer, and one depth per
// instance, so a single draw stacks `instanceCount` copies of a mesh. A negative step draws them
// back to front (every layer passes the LESS test and writes), a positive one front to back
// (every layer after the first is rejected).
layout(location = 0) in vec2 in_position;

layout(push_constant) uniform Layers {
  float first_depth;
  float depth_step;
}
layers;

void main() {
  gl_Position = vec4(in_position, layers.first_depth + float(gl_InstanceIndex) * layers.depth_step, 1.0);
}
