// SPDX-License-Identifier: MIT
// The scene's instances (systems/gpu/scene_gpu_types.h, GpuInstance on the C++ side), for every
// shader that places meshes in the world.
#ifndef SG_SCENE_INSTANCES_GLSL
#define SG_SCENE_INSTANCES_GLSL

#include "bindings.glsl"

struct Instance {
  mat4 model;
  vec4 base_color_specular; // rgb: base color, a: specular strength kS
  vec4 material;            // x: Blinn shininess s, y: base color texture index or -1,
                            // z: base color alpha, w: mask's alpha cutoff (0: no cut-out)
  uvec4 layers;             // x: the layers lights see it on (MeshInstance::light_layers); yzw: 0
};

layout(std430, set = 0, binding = instances_binding) readonly buffer Instances { Instance instances[]; };

#endif
