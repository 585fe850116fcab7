// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// The camera's depth buffer as grey: white at the near plane, black at `shown_distance`.
#include "depth_overlay_interface.glsl"

layout(set = 0, binding = depth_buffer_binding) uniform sampler2D depth_buffer;
layout(push_constant) uniform Constants { DepthOverlayLens lens; };

layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

void main() {
  float d = texture(depth_buffer, in_uv).r;
  // Inverse of the camera's reversed perspective depth (1 at znear, 0 at zfar, systems/gpu/camera.h):
  // view distance along the axis.
  float view_z = lens.znear * lens.zfar / (lens.znear + d * (lens.zfar - lens.znear));
  float grey = 1.0 - clamp(view_z / lens.shown_distance, 0.0, 1.0);
  out_color = vec4(vec3(grey), 1.0);
}
