#pragma once

// Small components shared by the ECS tests.
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

}  // namespace sg::ecs::test
