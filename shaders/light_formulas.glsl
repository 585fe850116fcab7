// SPDX-License-Identifier: MIT
// The scalar formulas of docs/ALGORITHMS.md that light_shading.glsl and
// shadow_sampling.glsl use. This file is also compiled as C++ (systems/shadows/
// light_formulas.cpp, GLM standing in for the GLSL built-ins), so the CPU tests check the very
// code the GPU runs. Keep it to what both languages read the same way: float, vec*, uvec*,
// mat4, built-in functions GLM also has, and an `f` on every float literal.
#ifndef SG_LIGHT_FORMULAS_GLSL
#define SG_LIGHT_FORMULAS_GLSL

// Rec. 709 luminance of a linear color: how bright a light or a sum of lights reads.
const vec3 LUMINANCE_WEIGHTS = vec3(0.2126f, 0.7152f, 0.0722f);
float luminance(vec3 color) { return dot(color, LUMINANCE_WEIGHTS); }

// Distance falloff, linear window (section 2): A = max(1 - d / R, 0).
float falloff_linear_window(float distance, float range) {
  return max(1.0f - distance / range, 0.0f);
}

// gltf_range_window from (d/R)^2, for a caller that has it without dividing by R.
float gltf_window(float ratio2) {
  float window = clamp(1.0f - ratio2 * ratio2, 0.0f, 1.0f);
  return window * window;
}

// The range window of glTF KHR_lights_punctual's falloff: clamp(1 - (d/R)^4, 0, 1)^2, 1 at the
// light and 0 from R on.
float gltf_range_window(float distance, float range) { return gltf_window((distance / range) * (distance / range)); }

// Distance falloff of glTF KHR_lights_punctual (section 2): A = clamp(1 - (d/R)^4, 0, 1)^2 / d^2.
// d^2 is held at 1 cm^2 or more so that a surface touching the light stays finite.
float falloff_gltf_punctual(float distance, float range) {
  return gltf_range_window(distance, range) / max(distance * distance, 1e-4f);
}

// Smooth spot rim (section 2), cos_angle = dot(D, -L):
// clamp((cos_angle - cos(outer)) / (cos(inner) - cos(outer)), 0, 1). Lights keep inner < outer;
// the floor on the denominator only keeps a degenerate cone from dividing by zero.
float spot_cone(float cos_angle, float cos_inner, float cos_outer) {
  return clamp((cos_angle - cos_outer) / max(cos_inner - cos_outer, 1e-6f), 0.0f, 1.0f);
}

// Cylinder ("target direct") light's lambda (section 2). `along` is dot(T, P_frag - P_light),
// whose sign is that of cosPhi = dot(-L, T): zero behind the light. `axis_distance` is
// delta = |cross(T, P_frag - P_light)|: 1 within the inner radius, linear to 0 at the outer.
float cylinder_lambda(float along, float axis_distance, float inner_radius, float outer_radius) {
  if (along < 0.0f) return 0.0f;
  if (axis_distance <= inner_radius) return 1.0f;
  return clamp((outer_radius - axis_distance) / (outer_radius - inner_radius), 0.0f, 1.0f);
}

// Section 4's bias: max(b1 * (1 - dot(N, L)), b0), in the normalized linear depth units of
// shadow_sampling.glsl.
float shadow_bias(float n_dot_l, float constant_bias, float slope_bias) {
  return max(slope_bias * (1.0f - n_dot_l), constant_bias);
}

// The perspective light projections (light_views.h: Vulkan depth, 0 at near n, 1 at far f) store
// d = (f - n f / z) / (f - n) for a point at view depth z (its distance along the light's axis).
// The inverse is docs/ALGORITHMS.md section 4.4's zView = Py / (d - Px) for this projection, with
// Px = f / (f - n) and Py = -n f / (f - n), which simplifies to n f / (f - d (f - n)).
float perspective_view_depth(float stored_depth, float near, float far) {
  return near * far / (far - stored_depth * (far - near));
}

// d(stored depth)/d(view depth) at view depth z: n f / ((f - n) z^2).
float perspective_stored_depth_slope(float view_depth, float near, float far) {
  return near * far / ((far - near) * view_depth * view_depth);
}

// PCSS penumbra width on the receiver, in world units (section 4.4 b), for perspective and cube
// maps: w = (zReceiver - zBlocker) / zBlocker * lightSize, depths measured from the light.
float pcss_penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return (receiver_depth - blocker_depth) / blocker_depth * light_size;
}

// The orthographic equivalent (directional and cylinder lights, rays parallel): the emitter is
// seen under a fixed angle, light_size being its width seen from one world unit away, so the
// penumbra grows with the blocker-receiver gap alone: w = (zReceiver - zBlocker) * lightSize.
float orthographic_penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return (receiver_depth - blocker_depth) * light_size;
}

// NDC x units per world unit of a light's shadow_matrix, on a plane facing the light at view
// depth 1 (perspective) or anywhere (orthographic): the length of the matrix's first row,
// because light view matrices are rigid and the projections have aspect 1.
float projection_x_scale(mat4 shadow_matrix) {
  return length(vec3(shadow_matrix[0][0], shadow_matrix[1][0], shadow_matrix[2][0]));
}

// Map uv units per world unit across a plane facing the light at `view_depth` (uv spans half
// the NDC range); turns world-space penumbra widths into filter radii.
float map_uv_per_world_unit(float x_scale, float view_depth, bool orthographic) {
  return 0.5f * x_scale / (orthographic ? 1.0f : view_depth);
}

// World size of one cube-map texel at `distance` from the light, at a face centre: a 90 degree
// face is 2 * distance wide there, spread over 1 / texel_uv texels.
float cube_texel_world_size(float distance, float texel_uv) {
  return 2.0f * distance * texel_uv;
}

// Vulkan's cube-map addressing ("Cube Map Face Selection" in the specification): the face of
// `direction`'s major axis and the point's (s, t) on it, as (s, t, face), faces +X, -X, +Y, -Y,
// +Z, -Z numbered 0..5. Point-light faces are rendered so that this reads the texel rendered in
// that direction (shadows/light_views.h, CubeViews), and they live as atlas tiles, so the
// shaders select the face themselves instead of sampling a cube image.
vec3 cube_face_uv(vec3 direction) {
  vec3 a = abs(direction);
  float face;
  float sc;
  float tc;
  float ma;
  if (a.x >= a.y && a.x >= a.z) {
    face = direction.x >= 0.0f ? 0.0f : 1.0f;
    sc = direction.x >= 0.0f ? -direction.z : direction.z;
    tc = -direction.y;
    ma = a.x;
  } else if (a.y >= a.z) {
    face = direction.y >= 0.0f ? 2.0f : 3.0f;
    sc = direction.x;
    tc = direction.y >= 0.0f ? direction.z : -direction.z;
    ma = a.y;
  } else {
    face = direction.z >= 0.0f ? 4.0f : 5.0f;
    sc = direction.z >= 0.0f ? direction.x : -direction.x;
    tc = -direction.y;
    ma = a.z;
  }
  float half_inverse = 0.5f / ma;  // one division, not two: CPU drivers wait on each
  return vec3(sc * half_inverse + 0.5f, tc * half_inverse + 0.5f, face);
}

// PCG-based integer hash (Jarzynski and Olano, "Hash Functions for GPU Rendering", 2020):
// every output bit depends on every input bit, with no floating-point precision loss.
uvec3 pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

// Three uniform numbers in (0, 1] for sample `index` in an integer cell: a shadow-map texel (the
// noise algorithms' rotations, shadow_sampling.glsl) or a screen pixel (the reference's jitter).
// The same cell gets the same numbers every frame: no time enters.
vec3 cell_random(uvec2 cell, uint index) {
  uvec3 h = pcg3d(uvec3(cell, index));
  return (vec3(h >> 8u) + 1.0f) / 16777216.0f;  // 24 bits, exact in a float
}

// Two independent standard normal numbers from two uniform ones in (0, 1] (Box-Muller, for the
// random rotations of docs/ALGORITHMS.md section 4.3): sqrt(-2 ln u1) * (cos(2 pi u2), sin(2 pi u2)).
vec2 gaussian_pair(vec2 u) {
  float radius = sqrt(-2.0f * log(u.x));
  float angle = 6.28318531f * u.y;
  return radius * vec2(cos(angle), sin(angle));
}

#endif
