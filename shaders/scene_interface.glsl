// Data the scene pass reads; must match systems/scene_gpu_types.h (the C++ side).
#ifndef SG_SCENE_INTERFACE_GLSL
#define SG_SCENE_INTERFACE_GLSL

#include "bindings.glsl"

struct Instance {
  mat4 model;
  mat4 normal_matrix;       // inverse transpose of the model matrix
  vec4 base_color_specular; // rgb: base colour, a: specular strength kS
  vec4 material;            // x: Blinn shininess s, y: base colour texture index or -1
};

layout(std430, set = 0, binding = instances_binding) readonly buffer Instances { Instance instances[]; };

layout(push_constant) uniform FrameConstants {
  mat4 view_projection;
  vec4 camera_position;  // xyz; w: the ambient term kA * IA
  uvec4 counts;          // x: lights in the Lights buffer; y: light tiles across the screen
} frame;

#endif
