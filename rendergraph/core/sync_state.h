// SPDX-License-Identifier: MIT
#pragma once

// The hazard-tracking rules: what is known about one subresource between passes, and the
// dependency a new use of it needs. Pure functions over plain data, so each rule is unit-tested.

#include <optional>

#include "rendergraph/core/compiled_plan.h"
#include "rendergraph/core/sync_types.h"

namespace sg::rg {

struct SyncState {
  ImageLayout layout = ImageLayout::undefined;
  // Stages after which the last write (or layout transition) is complete; none: nothing to wait for.
  PipelineStage write_stages = PipelineStage::none;
  // The last write's accesses while not yet made available; a barrier that waits for it clears it.
  Access write_access = Access::none;
  // Where the last write has been made visible; reads there need no barrier.
  PipelineStage visible_stages = PipelineStage::none;
  Access visible_access = Access::none;
  // Reads since the last write, which a later write or layout transition must wait for.
  PipelineStage read_stages = PipelineStage::none;
  Access read_access = Access::none;

  friend bool operator==(const SyncState&, const SyncState&) = default;
};

// Moves `state` to `use` and returns the dependency that must come before it, or nullopt when
// none is needed (a read already visible in the same layout, or a first write with nothing before).
std::optional<Dependency> advance(SyncState& state, const ResourceState& use);

// The state of an imported subresource last used as `last_use` (a previous frame's export).
SyncState imported_state(const ResourceState& last_use);

// The inverse of imported_state(): what an importer in the next frame must wait for.
ResourceState exported_state(const SyncState& state);

// The state of memory taken over from transients whose lifetimes ended: nothing in it is worth
// keeping (undefined layout), but their last uses must finish before the new owner writes.
SyncState reused_memory_state(const SyncState& previous_owner_last_use);

}  // namespace sg::rg
