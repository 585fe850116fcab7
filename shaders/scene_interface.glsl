// SPDX-License-Identifier: MIT
// Data the scene pass reads; must match systems/gpu/scene_gpu_types.h (the C++ side).
#ifndef SG_SCENE_INTERFACE_GLSL
#define SG_SCENE_INTERFACE_GLSL

#include "scene_instances.glsl"

layout(push_constant) uniform FrameConstants {
  mat4 view_projection;
  vec4 camera_position;  // xyz; w: unused
  uvec4 counts;          // x: lights; y: light tiles across the screen; z: exposure's bits (fused);
                         // w: 1 where the transparent pass blends into a tone-mapped frame
  vec4 ambient;          // rgb: the ambient term kA * IA
} frame;

#endif
