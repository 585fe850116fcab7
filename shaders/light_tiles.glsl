// SPDX-License-Identifier: MIT
// Tiled light culling (light_tiles.comp) and what the tiled lighting reads from it. Also compiled
// as C++ (tests/support/light_tiles_reference.cpp, Light standing for sg::shadows::GpuLight), so
// the CPU reference culls with the very same tests: keep to what both languages read alike.
#ifndef SG_LIGHT_TILES_GLSL
#define SG_LIGHT_TILES_GLSL

#include "light_tile_layout.glsl"

// The sphere around a tile's visible surfaces: the eight corners of the tile's slice of the
// view frustum between its nearest and farthest depth (Vulkan NDC, depth 0..1), brought back
// to world space. Loose for deep tiles, but the same on the CPU and the GPU.
vec4 tile_bounding_sphere(mat4 inverse_view_projection, vec2 ndc_min, vec2 ndc_max, float depth_min,
                          float depth_max) {
  vec3 corners[8];
  vec3 centre = vec3(0.0f);
  for (uint i = 0u; i < 8u; ++i) {
    vec4 ndc = vec4((i & 1u) != 0u ? ndc_max.x : ndc_min.x, (i & 2u) != 0u ? ndc_max.y : ndc_min.y,
                    (i & 4u) != 0u ? depth_max : depth_min, 1.0f);
    vec4 world = inverse_view_projection * ndc;
    corners[i] = vec3(world) / world.w;
    centre += corners[i];
  }
  centre *= 0.125f;
  float radius = 0.0f;
  for (uint i = 0u; i < 8u; ++i) radius = max(radius, length(corners[i] - centre));
  return vec4(centre, radius);
}

// Whether `light` can reach anything inside `sphere` (xyz centre, w radius): the point light's
// sphere of range, the spot light's cone (its sphere of range cut by the outer angle), the
// cylinder light's beam of outer radius in front of the light; a directional light reaches
// everything.
bool light_reaches_sphere(Light light, vec4 sphere) {
  uint type = light.info.x;
  if (type == LIGHT_DIRECTIONAL) return true;
  vec3 offset = vec3(sphere) - vec3(light.position_range);
  if (type == LIGHT_CYLINDER) {
    vec3 axis = vec3(light.direction_type);
    float along = dot(offset, axis);
    return along >= -sphere.w && length(cross(axis, offset)) <= light.shape.w + sphere.w;
  }
  float range = light.position_range.w;
  float distance = length(offset);
  if (distance > range + sphere.w) return false;
  if (type == LIGHT_POINT) return true;
  // Spot: the sphere against the cone (apex at the light, half angle `outer`).
  vec3 axis = vec3(light.direction_type);
  float along = dot(offset, axis);
  float across = sqrt(max(distance * distance - along * along, 0.0f));
  float cos_outer = light.shape.y;
  float sin_outer = sqrt(max(1.0f - cos_outer * cos_outer, 0.0f));
  float beyond_cone = cos_outer * across - along * sin_outer;  // distance from the cone's side
  return beyond_cone <= sphere.w && along >= -sphere.w;
}

#endif
