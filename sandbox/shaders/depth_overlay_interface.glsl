// SPDX-License-Identifier: MIT
// What the depth overlay's fragment shader reads, declared once for it and for the C++ that
// binds it (sandbox/depth_overlay_pass.cpp includes this file): a `const int` and a struct of
// floats read the same in GLSL and C++.
#ifndef SG_DEPTH_OVERLAY_INTERFACE_GLSL
#define SG_DEPTH_OVERLAY_INTERFACE_GLSL

const int depth_buffer_binding = 0;

// Push constants: the camera lens, and the distance shown as black.
struct DepthOverlayLens {
  float znear;
  float zfar;
  float shown_distance;
};

#endif
