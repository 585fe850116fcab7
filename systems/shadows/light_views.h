// SPDX-License-Identifier: MIT
#pragma once
// The cameras that render shadow maps, in the engine's conventions (systems/gpu/camera.h):
// right-handed world, Vulkan clip space with depth 0 at the near plane and 1 at the far plane,
// rendered with a positive-height viewport. The receiver side (shaders/shadow_sampling.glsl)
// maps clip space to map uv with u = (x + 1) / 2, v = (y + 1) / 2, as the rasterizer does.
#include <array>

#include <glm/glm.hpp>

#include "systems/scene/aabb.h"

namespace sg::shadows {

// A 2D shadow map's camera (spot, directional, cylinder lights).
struct LightView {
  glm::mat4 view{1.0f};        // world -> light view space (rigid; the light looks down -Z)
  glm::mat4 projection{1.0f};  // Vulkan clip space, NDC y down like systems/gpu/camera.cpp
  float near = 0.0f;           // world units along the light's axis
  float far = 1.0f;
  bool orthographic = false;

  glm::mat4 view_projection() const { return projection * view; }

  friend bool operator==(const LightView&, const LightView&) = default;
};

// The near plane of perspective light maps (spot faces and cube faces) for a light of range
// `range`: range / 200, held within [1 cm, 10 cm]. Casters nearer the light than this are
// clipped, so it is kept small, but not smaller: at far / near = 200 a D32_SFLOAT map resolves
// about 1e-5 of the range at the far plane, well inside the default constant bias of 5e-4 of
// the range (systems/scene/shadow_settings.h); D16_UNORM would resolve only 0.3%, too coarse
// for those biases, so use D32_SFLOAT. Beyond a range of 20 the ratio grows as near stays 10 cm.
float shadow_near_plane(float range);

// The widest perspective map a spot light gets: a cone of outer angle pi/2 (a hemisphere) cannot
// be projected onto one plane, so its map covers 170 degrees and the rim beyond is unshadowed.
inline constexpr float max_spot_shadow_fov = glm::radians(170.0f);

// Perspective map of a spot light at `position` shining along unit `direction`: square, fov
// 2 * outer_cone (at most max_spot_shadow_fov) so the cone's circle touches the map's sides,
// near shadow_near_plane(range), far = range.
LightView spot_light_view(glm::vec3 position, glm::vec3 direction, float outer_cone, float range);

// Orthographic map of a directional light shining along unit `direction`, fitted so that every
// corner of `bounds` (not empty) projects inside the map and its depth range, with a margin of
// 0.5% of the box's diagonal (at least 1 mm) on every side so receivers on the box's faces do
// not fall just outside through rounding.
LightView directional_light_view(glm::vec3 direction, const scene::Aabb& bounds);

// Orthographic map of a directional light over part of the scene: `whole` (its
// directional_light_view) narrowed to a square of half extent `half_extent` across the light
// around world point `centre`, its depth range kept. The square's centre is snapped to a lattice
// of spacing `snap` fixed in the light's frame (a cascade, cascades.h), so that centres within
// one lattice cell give the same map.
LightView directional_slice_view(const LightView& whole, glm::vec3 centre, float half_extent, float snap);

// Orthographic map of a cylinder light at `position` shining along unit `direction`: a square of
// half extent outer_radius around the beam axis, depth from the light (nothing behind it is lit,
// so nothing behind it can cast) to the farthest corner of `bounds` plus the same margin.
LightView cylinder_light_view(glm::vec3 position, glm::vec3 direction, float outer_radius,
                              const scene::Aabb& bounds);

// The six faces of a point light's cube map, in Vulkan's face order +X, -X, +Y, -Y, +Z, -Z:
// face f of cube c is layer 6c + f of the cube array. Each face is lookAt(P, P + axis, up)
// with docs/ALGORITHMS.md section 3.3's up vectors, 90 degrees, aspect 1, near shadow_near_plane(range),
// far = range. Unlike every other engine projection these keep NDC y pointing up (no flip):
// that is what makes the rendered face images line up with Vulkan's cube-map addressing, so that
// sampling with direction fragWorld - P reads the texel rendered in that direction (proved in
// tests/systems/shadows/light_views_test.cpp). It also mirrors the image, so triangles wind the other way
// than in 2D light maps: a cube-face pipeline that culls must flip its front face.
struct CubeViews {
  std::array<glm::mat4, 6> view_projection;  // std140/std430 mat4[6]: copy as is to the GPU
  float near = 0.0f;
  float far = 1.0f;
};

CubeViews point_light_cube(glm::vec3 position, float range);

// The six planes of a Vulkan view-projection's frustum (depth 0..1): left, right, top, bottom,
// near, far, each (n, d) with dot(n, p) + d >= 0 inside (not normalized).
std::array<glm::vec4, 6> frustum_planes(const glm::mat4& view_projection);

}  // namespace sg::shadows
