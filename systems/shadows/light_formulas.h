// SPDX-License-Identifier: MIT
#pragma once
// The shaders' lighting and shadow formulas on the CPU: these are the functions of
// shaders/light_formulas.glsl, compiled as C++ from that very file (light_formulas.cpp), so
// tests and CPU references evaluate exactly what the GPU does. The GLSL file documents each
// formula and its source in docs/ALGORITHMS.md.
#include <cstdint>

#include <glm/glm.hpp>

namespace sg::shadows::glsl {

float luminance(glm::vec3 color);
float falloff_linear_window(float distance, float range);
float gltf_window(float ratio2);
float gltf_range_window(float distance, float range);
float falloff_gltf_punctual(float distance, float range);
float spot_cone(float cos_angle, float cos_inner, float cos_outer);
float cylinder_lambda(float along, float axis_distance, float inner_radius, float outer_radius);
float shadow_bias(float n_dot_l, float constant_bias, float slope_bias);
float perspective_view_depth(float stored_depth, float near, float far);
float perspective_stored_depth_slope(float view_depth, float near, float far);
float pcss_penumbra_width(float receiver_depth, float blocker_depth, float light_size);
float orthographic_penumbra_width(float receiver_depth, float blocker_depth, float light_size);
float projection_x_scale(glm::mat4 shadow_matrix);
float map_uv_per_world_unit(float x_scale, float view_depth, bool orthographic);
float cube_texel_world_size(float distance, float texel_uv);
glm::vec3 cube_face_uv(glm::vec3 direction);
glm::uvec3 pcg3d(glm::uvec3 v);
glm::vec3 cell_random(glm::uvec2 cell, std::uint32_t index);
glm::vec2 gaussian_pair(glm::vec2 u);

}  // namespace sg::shadows::glsl
