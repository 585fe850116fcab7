// SPDX-License-Identifier: MIT
#version 460
// Dear ImGui's vertices (ImDrawVert: position in pixels, uv into the font atlas, color) into
// clip space: clip = position * scale + translate (sandbox/ui_pass.cpp).
layout(location = 0) in vec2 in_position;
layout(location = 1) in vec2 in_uv;
layout(location = 2) in vec4 in_color;

layout(push_constant) uniform UiTransform {
  vec2 scale;
  vec2 translate;  // then 16 bytes of ui_depth.frag's
} transform;

layout(location = 0) out vec2 out_uv;
layout(location = 1) out vec4 out_color;

void main() {
  out_uv = in_uv;
  out_color = in_color;
  gl_Position = vec4(in_position * transform.scale + transform.translate, 0.0, 1.0);
}
