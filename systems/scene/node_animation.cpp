// SPDX-License-Identifier: MIT
#include "systems/scene/node_animation.h"

#include <algorithm>
#include <cmath>

#include "ecs/query.h"
#include "ecs/transform.h"

namespace sg::scene {
namespace {

glm::quat as_quat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }
glm::vec4 as_vec4(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

}  // namespace

glm::vec4 sample(const AnimationChannel& channel, float time) {
  const std::vector<float>& times = channel.times;
  const bool cubic = channel.interpolation == Interpolation::cubic_spline;
  // The key's value (the middle of its three for cubic splines).
  const auto value = [&](std::size_t key) { return channel.values[cubic ? 3 * key + 1 : key]; };
  const auto normalized = [&](glm::vec4 v) {
    return channel.property == AnimatedProperty::rotation ? as_vec4(glm::normalize(as_quat(v))) : v;
  };
  if (times.empty()) return glm::vec4(0.0f);
  if (time <= times.front()) return normalized(value(0));
  if (time >= times.back()) return normalized(value(times.size() - 1));
  const auto next =
      static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), time) - times.begin());
  const std::size_t key = next - 1;
  const float span = times[next] - times[key];
  const float t = span > 0.0f ? (time - times[key]) / span : 0.0f;
  switch (channel.interpolation) {
    case Interpolation::step: return normalized(value(key));
    case Interpolation::linear:
      if (channel.property == AnimatedProperty::rotation) {
        return as_vec4(glm::slerp(as_quat(value(key)), as_quat(value(next)), t));
      }
      return glm::mix(value(key), value(next), t);
    case Interpolation::cubic_spline: {
      // glTF's Hermite spline: tangents are per second, so they scale by the keys' spacing.
      const glm::vec4 out_tangent = channel.values[3 * key + 2] * span;
      const glm::vec4 in_tangent = channel.values[3 * next] * span;
      const float t2 = t * t;
      const float t3 = t2 * t;
      return normalized((2 * t3 - 3 * t2 + 1) * value(key) + (t3 - 2 * t2 + t) * out_tangent +
                        (-2 * t3 + 3 * t2) * value(next) + (t3 - t2) * in_tangent);
    }
  }
  return value(key);
}

void animate_nodes(ecs::World& world, float time) {
  world.query<ecs::LocalTransform, const NodeAnimation>().for_each(
      [time](ecs::Entity, ecs::LocalTransform& local, const NodeAnimation& animation) {
        for (const AnimationChannel& channel : animation.channels) {
          const float local_time = channel.duration > 0.0f ? std::fmod(time, channel.duration) : 0.0f;
          const glm::vec4 v = sample(channel, local_time);
          switch (channel.property) {
            case AnimatedProperty::translation: local.translation = glm::vec3(v); break;
            case AnimatedProperty::rotation: local.rotation = as_quat(v); break;
            case AnimatedProperty::scale: local.scale = glm::vec3(v); break;
          }
        }
      });
}

}  // namespace sg::scene
