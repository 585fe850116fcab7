#version 460
// Dear ImGui's pixels: vertex colour times the font atlas (white where a shape has no glyph).
layout(set = 0, binding = 0) uniform sampler2D font_atlas;

layout(location = 0) in vec2 in_uv;
layout(location = 1) in vec4 in_colour;

layout(location = 0) out vec4 out_colour;

void main() { out_colour = in_colour * texture(font_atlas, in_uv); }
