// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// Distance fog over the frame: blended over the picture (alpha), thicker with the distance of the
// surface the camera's depth buffer holds; where it holds none (the sky), as thick as it gets.
#include "fog_interface.glsl"

layout(set = 0, binding = fog_depth_binding) uniform sampler2D depth_buffer;
layout(push_constant) uniform Constants { FogConstants fog; };

layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

void main() {
  float d = texture(depth_buffer, in_uv).r;
  // The engine's camera writes reversed perspective depth (1 at znear, 0 at zfar).
  float view_z = fog.znear * fog.zfar / (fog.znear + d * (fog.zfar - fog.znear));
  float amount = fog.thickest * clamp(view_z / fog.thickest_at, 0.0, 1.0);
  out_color = vec4(fog.red, fog.green, fog.blue, amount);
}
