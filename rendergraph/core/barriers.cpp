// SPDX-License-Identifier: MIT
#include "rendergraph/core/barriers.h"

#include <algorithm>

#include "rendergraph/core/span_map.h"
#include "rendergraph/core/sync_state.h"

namespace sg::rg {
namespace {

using Tracker = SubresourceMap<SyncState>;
using Pieces = std::vector<RangeValue<Dependency>>;

Tracker initial_tracker(const ResourceDeclaration& resource) {
  Tracker tracker(resource.mip_count(), resource.layer_count(), SyncState{});
  for (const RangeState& initial : resource.initial_states) {
    tracker.update(initial.range,
                   [&](const SubresourceRange&, SyncState& state) { state = imported_state(initial.state); });
  }
  return tracker;
}

// A transient that takes over memory starts out waiting for its previous occupants' last uses.
Tracker reused_memory_tracker(const ResourceDeclaration& resource, const MemoryPlacement& placement,
                              const std::vector<Tracker>& trackers) {
  SyncState last_use;
  for (std::uint32_t previous : placement.previous_occupants) {
    trackers[previous].for_each([&](const SubresourceRange&, const SyncState& state) {
      last_use.write_stages |= state.write_stages;
      last_use.write_access |= state.write_access;
      last_use.read_stages |= state.read_stages;
    });
  }
  return Tracker(resource.mip_count(), resource.layer_count(), reused_memory_state(last_use));
}

// Advances every subresource of `range` to `use`, collecting the dependencies needed.
void advance_range(Tracker& tracker, const SubresourceRange& range, const ResourceState& use,
                   Pieces& pieces) {
  tracker.update(range, [&](const SubresourceRange& piece, SyncState& state) {
    if (const auto dependency = advance(state, use)) pieces.push_back({piece, *dependency});
  });
}

void append(BarrierBatch& batch, std::uint32_t resource, ResourceKind kind, const Pieces& pieces) {
  for (const auto& [range, dependency] : merge_into_ranges(pieces)) {
    if (kind == ResourceKind::image) {
      batch.images.push_back({resource, range, dependency});
    } else {
      batch.buffers.push_back({resource, dependency});
    }
  }
}

// One pass's uses of one resource, merged per subresource: compatible reads of overlapping
// ranges (validated at declaration) become one use, so each subresource gets one barrier.
SubresourceMap<ResourceState> merged_uses(const ResourceDeclaration& resource,
                                          const std::vector<ResourceAccess>& accesses, std::uint32_t index) {
  SubresourceMap<ResourceState> uses(resource.mip_count(), resource.layer_count(), ResourceState{});
  for (const ResourceAccess& access : accesses) {
    if (access.resource != index) continue;
    uses.update(access.range, [&](const SubresourceRange&, ResourceState& use) {
      use.stages |= access.state.stages;
      use.access |= access.state.access;
      use.layout = access.state.layout;
    });
  }
  return uses;
}

}  // namespace

void plan_barriers(const RenderGraph& graph, CompiledPlan& plan) {
  const auto resources = graph.resources();
  std::vector<Tracker> trackers;
  trackers.reserve(resources.size());
  for (const ResourceDeclaration& resource : resources) trackers.push_back(initial_tracker(resource));

  for (std::uint32_t position = 0; position < plan.passes.size(); ++position) {
    CompiledPass& pass = plan.passes[position];
    std::vector<std::uint32_t> touched;
    for (const ResourceAccess& access : pass.accesses) {
      if (std::find(touched.begin(), touched.end(), access.resource) == touched.end())
        touched.push_back(access.resource);
    }
    for (std::uint32_t index : touched) {
      const CompiledResource& compiled = plan.resources[index];
      if (compiled.placement && compiled.lifetime->first == position &&
          !compiled.placement->previous_occupants.empty()) {
        trackers[index] = reused_memory_tracker(resources[index], *compiled.placement, trackers);
      }
      Pieces pieces;
      merged_uses(resources[index], pass.accesses, index)
          .for_each([&](const SubresourceRange& range, const ResourceState& use) {
            if (use != ResourceState{}) advance_range(trackers[index], range, use, pieces);
          });
      append(pass.barriers, index, compiled.kind, pieces);
    }
  }

  for (std::uint32_t index = 0; index < resources.size(); ++index) {
    const ResourceDeclaration& resource = resources[index];
    if (!resource.imported) continue;
    ExportedState exported{index, {}};
    if (resource.final_state) {
      Pieces pieces;
      advance_range(trackers[index], resource.whole(), *resource.final_state, pieces);
      append(plan.final_barriers, index, resource.kind, pieces);
      exported.states.push_back({resource.whole(), *resource.final_state});
    } else {
      std::vector<RangeValue<ResourceState>> pieces;
      trackers[index].for_each([&](const SubresourceRange& range, const SyncState& state) {
        pieces.push_back({range, exported_state(state)});
      });
      for (const auto& [range, state] : merge_into_ranges(pieces)) exported.states.push_back({range, state});
    }
    plan.exported_states.push_back(std::move(exported));
  }
}

}  // namespace sg::rg
