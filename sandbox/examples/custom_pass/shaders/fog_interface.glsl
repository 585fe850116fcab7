// SPDX-License-Identifier: MIT
// What the fog pass's fragment shader reads, declared once for it and for the C++ that binds it
// (fog_pass.cpp includes this file): a `const int` and a struct of floats read the same in GLSL
// and C++.
#ifndef FOG_INTERFACE_GLSL
#define FOG_INTERFACE_GLSL

const int fog_depth_binding = 0;

// Push constants: the camera lens, the distance at which the fog is thickest, and its color.
struct FogConstants {
  float znear;
  float zfar;
  float thickest_at;
  float thickest;  // the most the fog hides, 0..1
  float red;
  float green;
  float blue;
};

#endif
