#version 460
// Point-light cube faces store distance / far instead of the projection's depth, so that
// receivers compare length(fragWorld - P) / far in any direction (docs/LIGHTING.md section 3).
// Clear the faces to 1 (nothing within range) and depth-test LESS. Distances beyond far (the
// face corners reach past it) store 1, which reads as "nothing within range" too. The light's
// position and far plane come from the vertex stage (shadow_map.vert, shadow_cube_layered.vert,
// shadow_batch.vert), flat.

layout(location = 0) in vec3 in_world_position;
layout(location = 1) flat in vec4 in_light_position_far;  // xyz: light position, w: far plane (its range)

void main() {
  float distance = length(in_world_position - in_light_position_far.xyz);
  gl_FragDepth = min(distance / in_light_position_far.w, 1.0);
}
