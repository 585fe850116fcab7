// SPDX-License-Identifier: MIT
#version 460
// Dear ImGui's pixels: vertex color times the font atlas (white where a shape has no glyph).
layout(set = 0, binding = 0) uniform sampler2D font_atlas;

layout(location = 0) in vec2 in_uv;
layout(location = 1) in vec4 in_color;

layout(location = 0) out vec4 out_color;

void main() { out_color = in_color * texture(font_atlas, in_uv); }
