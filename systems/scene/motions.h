// SPDX-License-Identifier: MIT
#pragma once
// Simple procedural motions for entities (the stress scene's moving lights and crates, the
// sandbox's "orbit" and "bob" toggles): components that say how an entity moves, and per-frame
// systems that write its LocalTransform translation for a time in seconds. Each write marks
// LocalTransform changed, so shadow caches see the move. Run ecs::update_world_transforms after.
#include <glm/glm.hpp>

#include "ecs/world.h"

namespace sg::scene {

// Circles `center` in the horizontal plane.
struct OrbitMotion {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
  float angular_speed = 1.0f;  // radians per second
  float phase = 0.0f;          // radians at time 0
};

// Moves up and down around the height `base_height` (x and z untouched, so it combines with an
// orbit: run animate_bobs after animate_orbits).
struct BobMotion {
  float base_height = 0.0f;
  float amplitude = 0.5f;
  float angular_speed = 2.0f;  // radians per second
  float phase = 0.0f;          // radians at time 0
};

// Sets every OrbitMotion entity's translation for `time` (rotation untouched); with `threads`,
// on them.
void animate_orbits(ecs::World& world, float time, jobs::ThreadPool* threads = nullptr);

// Sets every BobMotion entity's height for `time`; with `threads`, on them.
void animate_bobs(ecs::World& world, float time, jobs::ThreadPool* threads = nullptr);

}  // namespace sg::scene
