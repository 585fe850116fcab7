#version 460
// Point-light cube faces store distance / far instead of the projection's depth, so that
// receivers compare length(fragWorld - P) / far in any direction (ALGORITHMS.md section 3).
// Clear the faces to 1 (nothing within range) and depth-test LESS. Distances beyond far (the
// face corners reach past it) store 1, which reads as "nothing within range" too.
// Push constants: bytes 64..79 (after the vertex stage's view_projection), the C++
// sg::shadows::ShadowPassConstants::light_position_far.

layout(location = 0) in vec3 in_world_position;

layout(push_constant) uniform CubeFacePass {
  layout(offset = 64) vec4 light_position_far;  // xyz: light position, w: far plane (its range)
} pass;

void main() {
  float distance = length(in_world_position - pass.light_position_far.xyz);
  gl_FragDepth = min(distance / pass.light_position_far.w, 1.0);
}
