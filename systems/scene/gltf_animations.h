// SPDX-License-Identifier: MIT
#pragma once
// glTF animations -> NodeAnimation components (node_animation.h): every channel that targets a
// node's translation, rotation or scale, with its sampler's keys, on the node's entity.
//
// Refused (SceneError naming the animation, channel or sampler): a channel whose sampler or
// node does not exist, an input that is not float scalars ascending from zero or more, an
// output of the wrong type or of a count that does not match the input's (three values a key
// for CUBICSPLINE). Kept with a warning: channels of other paths (morph-target weights) and
// channels targeting nodes outside the imported scene, both skipped.
#include <span>

#include <tiny_gltf.h>

#include "ecs/entity.h"
#include "systems/scene/gltf_source.h"
#include "systems/scene/scene.h"

namespace sg::scene {

// `node_entities[n]` is node n's entity, ecs::null_entity for nodes not imported.
void import_animations(const GltfSource& source, const tinygltf::Model& model,
                       std::span<const ecs::Entity> node_entities, Scene& scene);

}  // namespace sg::scene
