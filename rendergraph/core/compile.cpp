// SPDX-License-Identifier: MIT
#include "rendergraph/core/compile.h"

#include "rendergraph/core/aliasing.h"
#include "rendergraph/core/barriers.h"
#include "rendergraph/core/schedule.h"

namespace sg::rg {
namespace {

std::vector<CompiledResource> describe_resources(const RenderGraph& graph, const CompiledPlan& plan) {
  std::vector<CompiledResource> resources;
  resources.reserve(graph.resources().size());
  for (const ResourceDeclaration& resource : graph.resources()) {
    CompiledResource& compiled = resources.emplace_back();
    compiled.name = resource.name;
    compiled.kind = resource.kind;
    compiled.imported = resource.imported;
    compiled.image = resource.image;
    compiled.buffer = resource.buffer;
    compiled.version_count = static_cast<std::uint32_t>(resource.producers.size());
  }
  for (std::uint32_t position = 0; position < plan.passes.size(); ++position) {
    for (const ResourceAccess& access : plan.passes[position].accesses) {
      CompiledResource& resource = resources[access.resource];
      resource.image_usage |= image_usage(access.usage, access.direction);
      resource.buffer_usage |= buffer_usage(access.usage, access.direction);
      if (!resource.lifetime) resource.lifetime = Lifetime{position, position};
      resource.lifetime->last = position;
    }
  }
  return resources;
}

void place_transients(CompiledPlan& plan) {
  std::vector<AliasingRequest> requests;
  std::vector<std::uint32_t> requester;
  for (std::uint32_t index = 0; index < plan.resources.size(); ++index) {
    const CompiledResource& resource = plan.resources[index];
    if (resource.imported || !resource.lifetime) continue;
    requests.push_back(estimate_request(resource));
    requester.push_back(index);
    plan.memory.unaliased_bytes += requests.back().size;
  }
  AliasingPlan aliasing = plan_aliasing(requests);
  for (std::uint32_t request = 0; request < requests.size(); ++request) {
    MemoryPlacement& placement = aliasing.placements[request];
    for (std::uint32_t& previous : placement.previous_occupants) previous = requester[previous];
    plan.resources[requester[request]].placement = std::move(placement);
  }
  for (const MemoryHeap& heap : aliasing.heaps) plan.memory.aliased_bytes += heap.size;
  plan.heaps = std::move(aliasing.heaps);
}

}  // namespace

CompileResult compile(const RenderGraph& graph) {
  if (!graph.errors().empty()) return {nullptr, {graph.errors().begin(), graph.errors().end()}};

  auto plan = std::make_shared<CompiledPlan>();
  Schedule schedule = schedule_passes(graph);
  const auto passes = graph.passes();
  plan->passes.reserve(schedule.order.size());
  for (std::uint32_t position = 0; position < schedule.order.size(); ++position) {
    const PassDeclaration& pass = passes[schedule.order[position]];
    CompiledPass& compiled = plan->passes.emplace_back();
    compiled.declared_index = schedule.order[position];
    compiled.name = pass.name;
    compiled.queue = pass.queue;
    compiled.side_effects = pass.side_effects;
    compiled.accesses = pass.accesses;
    compiled.depends_on = std::move(schedule.depends_on[position]);
  }
  for (std::uint32_t index : schedule.culled) plan->culled.push_back({index, passes[index].name});
  plan->resources = describe_resources(graph, *plan);
  place_transients(*plan);
  plan_barriers(graph, *plan);
  return {std::move(plan), {}};
}

}  // namespace sg::rg
