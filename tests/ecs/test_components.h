// SPDX-License-Identifier: MIT
#pragma once

#include "ecs/world.h"

// Small components and spawners shared by the ECS tests.
namespace sg::ecs::test {

struct Position {
  float x = 0.0f;
  float y = 0.0f;
};

struct Velocity {
  float x = 0.0f;
  float y = 0.0f;
};

struct Frozen {};

inline Entity spawn_still(World& world) {
  const Entity entity = world.create();
  world.add<Position>(entity);
  return entity;
}

inline Entity spawn_moving(World& world, Velocity velocity = {}) {
  const Entity entity = spawn_still(world);
  world.add<Velocity>(entity, velocity);
  return entity;
}

}  // namespace sg::ecs::test
