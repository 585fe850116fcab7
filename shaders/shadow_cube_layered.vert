#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_shader_viewport_layer_array : require
// All six faces of one point light's cube map in one draw (the single-pass option of
// ALGORITHMS.md section 3), with shadow_cube.frag. Draw the casters as for one face but with
// instanceCount x 6 (firstInstance unchanged): copy k of a draw renders caster
// gl_BaseInstance + k / 6 of the view's list (shadow_casters.glsl) into face k % 6, selected by
// writing gl_Layer. Render into a 6-layer view of the cube (layers 6c .. 6c + 5 of the array),
// so gl_Layer is the face.
//
// Device features: shaderOutputLayer (Vulkan 1.2; SPIR-V capability ShaderLayer) to write
// gl_Layer from a vertex shader, and shaderDrawParameters (gl_BaseInstance).
//
// Resources: Instances (scene_interface.glsl), the view's casters (shadow_casters.glsl) and the
// cube's six face matrices (sg::shadows::CubeViews::view_projection, e.g. one 384-byte slice per
// point light of one buffer, bound with a dynamic offset). Push constants as for
// shadow_cube.frag.
#include "scene_interface.glsl"
#include "shadow_casters.glsl"

layout(std140, set = 0, binding = cube_faces_binding) uniform CubeFaces {
  mat4 face_view_projection[6];  // +X, -X, +Y, -Y, +Z, -Z
} cube;

layout(location = 0) in vec3 in_position;

layout(location = 0) out vec3 out_world_position;

void main() {
  int copy = gl_InstanceIndex - gl_BaseInstance;
  int face = copy % 6;
  vec4 world = instances[view_instances[gl_BaseInstance + copy / 6]].model * vec4(in_position, 1.0);
  out_world_position = world.xyz;
  gl_Position = cube.face_view_projection[face] * world;
  gl_Layer = face;
}
