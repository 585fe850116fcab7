// SPDX-License-Identifier: MIT
// The push constants of tiled deferred lighting's passes (systems/lighting/tiled_lighting_pass.cpp,
// LightingConstants), shared by their compute and raster shapes.
#ifndef SG_TILED_LIGHTING_FRAME_GLSL
#define SG_TILED_LIGHTING_FRAME_GLSL

layout(push_constant) uniform Constants {
  mat4 inverse_view_projection;  // the camera's: positions from the depth buffer
  vec4 camera_position;
  uvec4 screen;  // x width, y height, z tiles across, w tiles in all
  uvec4 lights;  // x: the group's light where SINGLE_LIGHT; a group set's lights, one a group in order
  uvec4 set;     // x: a group set pass's place among the frame's sets (tiled_lighting.glsl)
} frame;

#endif
