// SPDX-License-Identifier: MIT
// The camera's depth buffer as the lighting passes read it: reversed (systems/gpu/camera.h), 1 at
// the near plane, 0 at the far plane and where nothing was drawn.
#ifndef SG_CAMERA_DEPTH_GLSL
#define SG_CAMERA_DEPTH_GLSL

const float CAMERA_FAR_DEPTH = 0.0;

bool is_background_depth(float depth) { return depth <= CAMERA_FAR_DEPTH; }

#endif
