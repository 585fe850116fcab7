// SPDX-License-Identifier: MIT
#pragma once
// Keyframed node animation as glTF defines it (animations' channels and samplers): a node's
// translation, rotation or scale sampled at a time, LINEAR (rotations by slerp), STEP or
// CUBICSPLINE, looping over its animation's duration. Imported from glTF (gltf_animations.h);
// animate_nodes() is the per-frame system.
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "ecs/world.h"

namespace sg::scene {

enum class AnimatedProperty { translation, rotation, scale };
enum class Interpolation { linear, step, cubic_spline };

struct AnimationChannel {
  AnimatedProperty property = AnimatedProperty::translation;
  Interpolation interpolation = Interpolation::linear;
  std::vector<float> times;  // ascending, seconds
  // Per key: the value (xyz for translation and scale; quaternion x, y, z, w for rotation). For
  // cubic_spline three per key, as glTF stores them: in-tangent, value, out-tangent.
  std::vector<glm::vec4> values;
  float duration = 0.0f;  // its animation's length: the channel loops over it
};

// On an animated node's entity: its channels (of any of the file's animations).
struct NodeAnimation {
  std::vector<AnimationChannel> channels;
};

// `channel`'s value at `time` seconds (already within [0, duration]): before the first key the
// first value, after the last the last value. Rotations come out normalized.
glm::vec4 sample(const AnimationChannel& channel, float time);

// Per-frame system: sets the LocalTransform of every NodeAnimation entity for `time` seconds
// (each channel looping over its duration), marking LocalTransform changed so that shadow
// caches see the move. Run ecs::update_world_transforms afterwards.
void animate_nodes(ecs::World& world, float time);

}  // namespace sg::scene
