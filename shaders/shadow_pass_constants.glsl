// SPDX-License-Identifier: MIT
// The per-light shadow passes' push constants (shadow_map.vert, shadow_cube_layered.vert); must
// match PassConstants in systems/shadow_maps/shadow_passes.cpp. Those shaders take the scene's
// instances alone (scene_instances.glsl), not scene_interface.glsl's larger FrameConstants: a block
// larger than the layout's range is an error (VUID-VkGraphicsPipelineCreateInfo-layout-10069).
#ifndef SG_SHADOW_PASS_CONSTANTS_GLSL
#define SG_SHADOW_PASS_CONSTANTS_GLSL

layout(push_constant) uniform PassConstants {
  mat4 view_projection;     // the light view's (LightView::view_projection() or one CubeViews face)
  vec4 light_position_far;  // cube faces: the light's position and far plane, for shadow_cube.frag
} pass;

#endif
