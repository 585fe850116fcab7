// SPDX-License-Identifier: MIT
#pragma once
// Which shadow casters changed since the last frame, as the boxes a cached shadow map could have
// changed in. ShadowCache (shadow_cache.h) re-renders exactly the lights whose reach meets one of
// these boxes, so a box left out here is a stale shadow on screen.
#include <cstdint>
#include <span>
#include <vector>

#include "systems/scene/aabb.h"
#include "systems/scene/layers.h"

namespace sg::shadows {

// One shadow caster of a frame. `key` is its entity's identity, ecs::entity_key(entity)
// (generation << 32 | index): the low 32 bits index the tracker's storage
// (so it grows to the largest slot index seen), the high 32 bits tell a destroyed entity from
// the one that reuses its slot.
struct CasterBounds {
  uint64_t key = 0;
  scene::Aabb bounds;
  scene::LayerMask layers = scene::first_layer;  // MeshInstance::shadow_layers
};

class CasterChangeTracker {
 public:
  // Call once per frame with every shadow caster of the frame, in any order, each key once.
  // Returns the boxes a shadow could have changed in since the previous call:
  // - a caster whose box moved or changed size (any coordinate differs): its old and its new box;
  // - a caster whose shadow layers changed: its box (the lights that draw it are others now);
  // - a caster that is new (its key was not in the previous call): its box;
  // - a caster that is gone (in the previous call, not in this one): its old box.
  // Empty boxes are never reported: they shadow nothing.
  // The first call reports nothing: there is no earlier frame to compare with, and every light is
  // new to ShadowCache then, so it renders every light anyway.
  // The span stays valid until the next call. Once the storage has grown to the frame's slot
  // indices and caster count, a call allocates nothing.
  std::span<const scene::Aabb> update(std::span<const CasterBounds> casters);

 private:
  struct Slot {
    uint32_t generation = 0;
    uint64_t frame = 0;  // the call that last saw this slot's caster; 0: never seen
    scene::Aabb bounds;
    scene::LayerMask layers = scene::first_layer;
  };

  void report(const scene::Aabb& box);

  uint64_t frame_ = 0;
  std::vector<Slot> slots_;                 // by slot index, the low 32 bits of the key
  std::vector<uint32_t> previous_indices_;  // the slot indices of the previous call's casters
  std::vector<uint32_t> current_indices_;
  std::vector<scene::Aabb> changes_;
};

}  // namespace sg::shadows
