// SPDX-License-Identifier: MIT
// Keyframed node animation: glTF's three interpolations, looping, and the system writing
// LocalTransform through the ECS.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "ecs/transform.h"
#include "ecs/world.h"
#include "systems/scene/node_animation.h"

namespace sg::scene {
namespace {

AnimationChannel translation(Interpolation interpolation, std::vector<float> times,
                             std::vector<glm::vec4> values) {
  AnimationChannel channel;
  channel.property = AnimatedProperty::translation;
  channel.interpolation = interpolation;
  channel.times = std::move(times);
  channel.values = std::move(values);
  channel.duration = channel.times.back();
  return channel;
}

void expect_near(const glm::vec4& actual, const glm::vec4& expected) {
  EXPECT_LT(glm::length(actual - expected), 1e-5f)
      << actual.x << ", " << actual.y << ", " << actual.z << ", " << actual.w;
}

TEST(NodeAnimation, LinearInterpolatesAndHoldsTheEnds) {
  const AnimationChannel channel =
      translation(Interpolation::linear, {1.0f, 3.0f}, {glm::vec4(0, 0, 0, 0), glm::vec4(4, 2, 0, 0)});
  expect_near(sample(channel, 0.0f), {0, 0, 0, 0});  // before the first key: the first value
  expect_near(sample(channel, 2.0f), {2, 1, 0, 0});
  expect_near(sample(channel, 2.5f), {3, 1.5f, 0, 0});
  expect_near(sample(channel, 9.0f), {4, 2, 0, 0});
}

TEST(NodeAnimation, StepHoldsEachKeyUntilTheNext) {
  const AnimationChannel channel =
      translation(Interpolation::step, {0.0f, 1.0f, 2.0f},
                  {glm::vec4(1, 0, 0, 0), glm::vec4(2, 0, 0, 0), glm::vec4(3, 0, 0, 0)});
  expect_near(sample(channel, 0.99f), {1, 0, 0, 0});
  expect_near(sample(channel, 1.0f), {2, 0, 0, 0});
  expect_near(sample(channel, 1.5f), {2, 0, 0, 0});
}

TEST(NodeAnimation, CubicSplineFollowsGltfsHermiteWithTangentsPerSecond) {
  // Keys at 0 and 2 s, values 0 and 1, out-tangent of the first 1/s, in-tangent of the second 0.
  const AnimationChannel channel = translation(
      Interpolation::cubic_spline, {0.0f, 2.0f},
      {glm::vec4(0), glm::vec4(0), glm::vec4(1, 0, 0, 0), glm::vec4(0), glm::vec4(1, 0, 0, 0), glm::vec4(0)});
  // t = 0.5: (2t^3 - 3t^2 + 1) * 0 + (t^3 - 2t^2 + t) * (1 * 2) + (-2t^3 + 3t^2) * 1 + (t^3 - t^2) * 0
  expect_near(sample(channel, 1.0f), {0.125f * 2.0f + 0.5f, 0, 0, 0});
  expect_near(sample(channel, 2.0f), {1, 0, 0, 0});
}

TEST(NodeAnimation, LinearRotationsSlerpAndStayUnit) {
  AnimationChannel channel;
  channel.property = AnimatedProperty::rotation;
  const glm::quat a = glm::angleAxis(0.0f, glm::vec3(0, 1, 0));
  const glm::quat b = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
  channel.times = {0.0f, 1.0f};
  channel.values = {glm::vec4(a.x, a.y, a.z, a.w), glm::vec4(b.x, b.y, b.z, b.w)};
  channel.duration = 1.0f;
  const glm::vec4 half = sample(channel, 0.5f);
  const glm::quat expected = glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 1, 0));
  expect_near(half, {expected.x, expected.y, expected.z, expected.w});
}

TEST(NodeAnimation, TheSystemLoopsAndMarksTheTransformChanged) {
  ecs::World world;
  const ecs::Entity node = world.create();
  world.add<ecs::LocalTransform>(node);
  world.add<NodeAnimation>(node,
                           NodeAnimation{{translation(Interpolation::linear, {0.0f, 2.0f},
                                                      {glm::vec4(0, 0, 0, 0), glm::vec4(2, 0, 0, 0)})}});
  const ecs::Tick before = world.advance_tick();
  animate_nodes(world, 5.0f);  // 5 s loop over 2 s: 1 s in
  EXPECT_FLOAT_EQ(world.get<ecs::LocalTransform>(node).translation.x, 1.0f);
  EXPECT_GE(world.change_tick<ecs::LocalTransform>(node), before);
}

}  // namespace
}  // namespace sg::scene
