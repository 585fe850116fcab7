#include "systems/scene/motions.h"

#include <cmath>

#include "ecs/transform.h"
#include "ecs/transform_system.h"

namespace sg::scene {

namespace {

// Runs `move` over the query, on `threads` when given.
template <class Query, class Move>
void move_all(Query query, ecs::ThreadPool* threads, const Move& move) {
  if (threads != nullptr) {
    query.for_each_parallel(*threads, move, ecs::motion_entities_per_task);
  } else {
    query.for_each(move);
  }
}

}  // namespace

void animate_orbits(ecs::World& world, float time, ecs::ThreadPool* threads) {
  move_all(world.query<ecs::LocalTransform, const OrbitMotion>(), threads,
           [time](ecs::LocalTransform& local, const OrbitMotion& orbit) {
             const float angle = orbit.phase + orbit.angular_speed * time;
             local.translation =
                 orbit.center + orbit.radius * glm::vec3(std::cos(angle), 0.0f, std::sin(angle));
           });
}

void animate_bobs(ecs::World& world, float time, ecs::ThreadPool* threads) {
  move_all(world.query<ecs::LocalTransform, const BobMotion>(), threads,
           [time](ecs::LocalTransform& local, const BobMotion& bob) {
             local.translation.y =
                 bob.base_height + bob.amplitude * std::sin(bob.phase + bob.angular_speed * time);
           });
}

}  // namespace sg::scene
