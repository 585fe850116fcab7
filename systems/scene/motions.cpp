// SPDX-License-Identifier: MIT
#include "systems/scene/motions.h"

#include <cmath>

#include "ecs/query.h"
#include "ecs/transform.h"
#include "ecs/transform_system.h"

namespace sg::scene {

void animate_orbits(ecs::World& world, float time, jobs::ThreadPool* threads) {
  world.query<ecs::LocalTransform, const OrbitMotion>().for_each_parallel(
      threads,
      [time](ecs::LocalTransform& local, const OrbitMotion& orbit) {
        const float angle = orbit.phase + orbit.angular_speed * time;
        local.translation = orbit.center + orbit.radius * glm::vec3(std::cos(angle), 0.0f, std::sin(angle));
      },
      ecs::motion_entities_per_task);
}

void animate_bobs(ecs::World& world, float time, jobs::ThreadPool* threads) {
  world.query<ecs::LocalTransform, const BobMotion>().for_each_parallel(
      threads,
      [time](ecs::LocalTransform& local, const BobMotion& bob) {
        local.translation.y =
            bob.base_height + bob.amplitude * std::sin(bob.phase + bob.angular_speed * time);
      },
      ecs::motion_entities_per_task);
}

}  // namespace sg::scene
