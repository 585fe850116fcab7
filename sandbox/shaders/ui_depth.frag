// SPDX-License-Identifier: MIT
#version 460
// A shadow map shown in a panel: the atlas layer's depth as grey, near black, far white.
// Perspective 2D maps store projected depth, which is made linear again (light_formulas.glsl);
// orthographic maps and cube faces (distance / far) already are.
#extension GL_GOOGLE_include_directive : require
#include "light_formulas.glsl"

layout(set = 0, binding = 0) uniform sampler2DArray shadow_atlas;

layout(location = 0) in vec2 in_uv;
layout(location = 1) in vec4 in_color;

layout(location = 0) out vec4 out_color;

layout(push_constant) uniform DepthView {
  layout(offset = 16) vec4 depth;  // x: atlas layer; y: near, z: far (perspective); w: 1 when linear
} view;

void main() {
  float stored = textureLod(shadow_atlas, vec3(in_uv, view.depth.x), 0.0).r;
  float near = view.depth.y, far = view.depth.z;
  float linear = view.depth.w > 0.5 ? stored
                                    : (perspective_view_depth(stored, near, far) - near) / (far - near);
  out_color = vec4(vec3(linear), 1.0) * in_color;
}
