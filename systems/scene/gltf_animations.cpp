// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_animations.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "systems/scene/gltf_accessor.h"
#include "systems/scene/gltf_json.h"
#include "systems/scene/node_animation.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {
namespace {

std::optional<AnimatedProperty> property_of(const std::string& path) {
  if (path == "translation") return AnimatedProperty::translation;
  if (path == "rotation") return AnimatedProperty::rotation;
  if (path == "scale") return AnimatedProperty::scale;
  return std::nullopt;
}

// The sampler's keys and values as a channel of `property`, checked against the glTF spec.
AnimationChannel read_channel(const GltfSource& source, const tinygltf::Model& model,
                              const tinygltf::AnimationSampler& sampler, AnimatedProperty property,
                              const std::string& object) {
  AnimationChannel channel;
  channel.property = property;
  if (sampler.interpolation.empty() || sampler.interpolation == "LINEAR") {
    channel.interpolation = Interpolation::linear;
  } else if (sampler.interpolation == "STEP") {
    channel.interpolation = Interpolation::step;
  } else if (sampler.interpolation == "CUBICSPLINE") {
    channel.interpolation = Interpolation::cubic_spline;
  } else {
    throw SceneError(source.path, object, "unknown interpolation \"" + sampler.interpolation + "\"");
  }
  const auto accessor_at = [&](int index, const char* role) -> const tinygltf::Accessor& {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
      throw SceneError(source.path, object,
                       std::string(role) + " accessor " + std::to_string(index) + " does not exist");
    }
    return model.accessors[static_cast<std::size_t>(index)];
  };
  const tinygltf::Accessor& input = accessor_at(sampler.input, "input");
  if (input.type != TINYGLTF_TYPE_SCALAR || input.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
    throw SceneError(source.path, object, "input is not float scalars");
  }
  for (const double t : read_accessor(model, static_cast<std::size_t>(sampler.input), source.path)) {
    if (!std::isfinite(t) || t < 0.0 || (!channel.times.empty() && t < channel.times.back())) {
      throw SceneError(source.path, object, "input times are not finite, ascending and at least zero");
    }
    channel.times.push_back(static_cast<float>(t));
  }
  if (channel.times.empty()) throw SceneError(source.path, object, "input has no keys");

  const tinygltf::Accessor& output = accessor_at(sampler.output, "output");
  const int components = property == AnimatedProperty::rotation ? 4 : 3;
  if (output.type != (components == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3)) {
    throw SceneError(source.path, object,
                     std::string("output is not ") + (components == 4 ? "VEC4" : "VEC3"));
  }
  const std::vector<double> values =
      read_accessor(model, static_cast<std::size_t>(sampler.output), source.path);
  const std::size_t per_key = channel.interpolation == Interpolation::cubic_spline ? 3 : 1;
  if (values.size() != channel.times.size() * per_key * components) {
    throw SceneError(source.path, object,
                     "output has " + std::to_string(values.size() / components) + " values for " +
                         std::to_string(channel.times.size()) + " keys" +
                         (per_key == 3 ? " (CUBICSPLINE: 3 a key)" : ""));
  }
  for (std::size_t v = 0; v < values.size(); v += components) {
    glm::vec4 value(0.0f);
    for (int c = 0; c < components; ++c) value[c] = static_cast<float>(values[v + c]);
    channel.values.push_back(value);
  }
  return channel;
}

}  // namespace

void import_animations(const GltfSource& source, const tinygltf::Model& model,
                       std::span<const ecs::Entity> node_entities, Scene& scene) {
  bool unsupported_warned = false;
  bool outside_warned = false;
  for (std::size_t a = 0; a < model.animations.size(); ++a) {
    const tinygltf::Animation& animation = model.animations[a];
    std::vector<std::pair<ecs::Entity, AnimationChannel>> channels;
    float duration = 0.0f;
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
      const tinygltf::AnimationChannel& target = animation.channels[c];
      const std::string object = indexed("animations", a) + "." + indexed("channels", c);
      const std::optional<AnimatedProperty> property = property_of(target.target_path);
      if (!property) {
        if (!unsupported_warned) {
          warn(scene, object + ": targets \"" + target.target_path +
                          "\", which is not animated (translation, rotation and scale are)");
        }
        unsupported_warned = true;
        continue;
      }
      if (target.target_node < 0 || static_cast<std::size_t>(target.target_node) >= node_entities.size()) {
        throw SceneError(source.path, object,
                         "targets node " + std::to_string(target.target_node) + ", which does not exist");
      }
      if (target.sampler < 0 || static_cast<std::size_t>(target.sampler) >= animation.samplers.size()) {
        throw SceneError(source.path, object,
                         "sampler " + std::to_string(target.sampler) + " does not exist");
      }
      const ecs::Entity entity = node_entities[static_cast<std::size_t>(target.target_node)];
      if (entity == ecs::null_entity) {
        if (!outside_warned) warn(scene, object + ": targets a node outside the imported scene; skipped");
        outside_warned = true;
        continue;
      }
      const std::string sampler_object =
          indexed("animations", a) + "." + indexed("samplers", static_cast<std::size_t>(target.sampler));
      AnimationChannel channel =
          read_channel(source, model, animation.samplers[static_cast<std::size_t>(target.sampler)], *property,
                       sampler_object);
      duration = std::max(duration, channel.times.back());
      channels.emplace_back(entity, std::move(channel));
    }
    // Every channel of an animation loops over the animation's whole length.
    for (auto& [entity, channel] : channels) {
      channel.duration = duration;
      if (scene.world.has<NodeAnimation>(entity)) {
        scene.world.get_mut<NodeAnimation>(entity).channels.push_back(std::move(channel));
      } else {
        scene.world.add<NodeAnimation>(entity, NodeAnimation{{std::move(channel)}});
      }
    }
  }
}

}  // namespace sg::scene
