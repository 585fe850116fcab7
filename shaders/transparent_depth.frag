#version 460
// The transparent surfaces' depth bounds per pixel, for light culling (light_tiles_interface.glsl):
// blended with max into a target cleared to (0, -1), x keeps the nearest depth (reversed: the
// greatest) and y minus the farthest. Drawn after depth_prepass.vert, tested against the opaque
// depth, so only surfaces in front of it count.
layout(location = 0) out vec2 out_bounds;

void main() { out_bounds = vec2(gl_FragCoord.z, -gl_FragCoord.z); }
