// SPDX-License-Identifier: MIT
#pragma once
// The shadow tests' scene: a grey floor (its top at y = 0, 20 x 20 m), a box above it and one
// spot, point or directional light, seen from above at an angle; and its exact CPU reference
// (shadow_reference.h). Shared by the shadow algorithm tests and the ray-traced reference's.
#include <cstdint>

#include <glm/glm.hpp>

#include "ecs/transform.h"
#include "systems/scene/scene.h"
#include "systems/scene/shadow_settings.h"
#include "tests/support/shadow_reference.h"

namespace sg::test {

inline constexpr float floor_half_extent = 10.0f;

enum class LightKind { spot, point, directional };

struct ShadowScene {
  LightKind kind = LightKind::spot;
  glm::vec3 light_position{-3.0f, 6.0f, -2.0f};  // off to the side: the shadow falls toward the camera
  scene::ShadowSettings shadow;
  float box_bottom = 1.0f;  // height of the occluder's underside above the floor
  float intensity = 1.6f;
  bool with_box = true;
  glm::vec3 aim{0.0f, -1.0f, 0.001f};  // the spot's or directional light's direction
  // Above floor_half_extent: two small boxes at (+-scene_half_extent, 0, +-scene_half_extent),
  // out of the camera's sight, widen the scene's bounds (and a directional light's fitted map).
  float scene_half_extent = 0.0f;

  friend bool operator==(const ShadowScene&, const ShadowScene&) = default;
};

// Where the reference puts `s`'s light: a directional light's far along its rays.
glm::vec3 reference_light_position(const ShadowScene& s);

// The occluder: a 1.6 x 0.5 x 1.2 m box turned 0.5 rad about +Y, its underside at box_bottom.
ecs::LocalTransform box_placement(const ShadowScene& s);

// Lights shine down their local -Z, the way cameras look.
ecs::LocalTransform aimed_light(glm::vec3 position, glm::vec3 direction);

// A scene with the grey floor (no specular term, so shade stays measurable) and the box mesh,
// whose index goes to `box`, for the caller to fill.
scene::Scene floor_scene(const char* name, uint32_t& box);

// `s` built, its light at `intensity`, world transforms up to date.
scene::Scene build_shadow_scene(const ShadowScene& s, float intensity);

// The camera the tests look through, for an image of `size` pixels.
CameraImage floor_camera(glm::uvec2 size);

// Every pixel of floor_camera(size) classified by exact ray casting, with an edge band of
// `band` pixels (with_edge_band).
FloorPixels floor_reference(const ShadowScene& s, glm::uvec2 size, int band);

}  // namespace sg::test
