// SPDX-License-Identifier: MIT
#include "rendergraph/core/sync_state.h"

namespace sg::rg {

std::optional<Dependency> advance(SyncState& state, const ResourceState& use) {
  const bool transition = state.layout != use.layout;
  const bool writes = is_write(use.access);
  const bool written = any(state.write_stages);
  const bool hazard = writes ? written || any(state.read_stages)
                             : written && !(contains(state.visible_stages, use.stages) &&
                                            contains(state.visible_access, use.access));
  if (!transition && !hazard) {
    if (writes) {
      state = {.layout = use.layout, .write_stages = use.stages, .write_access = use.access & write_accesses};
    } else {
      state.read_stages |= use.stages;
      state.read_access |= use.access;
    }
    return std::nullopt;
  }

  // A layout transition writes the image, so like any write it waits for earlier reads too.
  const Dependency dependency{
      .src_stages = state.write_stages | (writes || transition ? state.read_stages : PipelineStage::none),
      .src_access = state.write_access,
      .dst_stages = use.stages,
      .dst_access = use.access,
      .old_layout = state.layout,
      .new_layout = use.layout,
  };
  if (writes) {
    state = {.layout = use.layout, .write_stages = use.stages, .write_access = use.access & write_accesses};
  } else if (transition) {
    // The transition completes before the destination stages and is visible to them.
    state = {.layout = use.layout,
             .write_stages = use.stages,
             .visible_stages = use.stages,
             .visible_access = use.access,
             .read_stages = use.stages,
             .read_access = use.access};
  } else {
    state.write_access = Access::none;
    state.visible_stages |= use.stages;
    state.visible_access |= use.access;
    state.read_stages |= use.stages;
    state.read_access |= use.access;
  }
  return dependency;
}

SyncState imported_state(const ResourceState& last_use) {
  const Access reads = last_use.access & ~write_accesses;
  // Whatever wrote the resource before is complete after last_use's stages; writes listed in
  // last_use may still need to be made available, reads listed are where it is visible.
  return {.layout = last_use.layout,
          .write_stages = last_use.stages,
          .write_access = last_use.access & write_accesses,
          .visible_stages = any(reads) ? last_use.stages : PipelineStage::none,
          .visible_access = reads,
          .read_stages = any(reads) ? last_use.stages : PipelineStage::none,
          .read_access = reads};
}

ResourceState exported_state(const SyncState& state) {
  return {.stages = state.write_stages | state.read_stages,
          .access = state.write_access | state.read_access,
          .layout = state.layout};
}

SyncState reused_memory_state(const SyncState& previous_owner_last_use) {
  return {.write_stages = previous_owner_last_use.write_stages | previous_owner_last_use.read_stages,
          .write_access = previous_owner_last_use.write_access};
}

}  // namespace sg::rg
