// SPDX-License-Identifier: MIT
#include <nlohmann/json.hpp>

#include "rendergraph/core/dump.h"

namespace sg::rg {
namespace {

using nlohmann::json;

json range_json(const SubresourceRange& range) {
  return {{"base_mip", range.base_mip},
          {"mip_count", range.mip_count},
          {"base_layer", range.base_layer},
          {"layer_count", range.layer_count}};
}

json dependency_json(const Dependency& dependency) {
  return {{"src_stages", to_string(dependency.src_stages)}, {"src_access", to_string(dependency.src_access)},
          {"dst_stages", to_string(dependency.dst_stages)}, {"dst_access", to_string(dependency.dst_access)},
          {"old_layout", to_string(dependency.old_layout)}, {"new_layout", to_string(dependency.new_layout)}};
}

json batch_json(const BarrierBatch& batch, const CompiledPlan& plan) {
  json images = json::array();
  for (const ImageBarrier& barrier : batch.images) {
    json entry = dependency_json(barrier.dependency);
    entry["resource"] = plan.resources[barrier.resource].name;
    entry["range"] = range_json(barrier.range);
    images.push_back(std::move(entry));
  }
  json buffers = json::array();
  for (const BufferBarrier& barrier : batch.buffers) {
    json entry = dependency_json(barrier.dependency);
    entry["resource"] = plan.resources[barrier.resource].name;
    buffers.push_back(std::move(entry));
  }
  return {{"images", std::move(images)}, {"buffers", std::move(buffers)}};
}

json pass_json(const CompiledPass& pass, std::uint32_t position, const CompiledPlan& plan,
               std::span<const double> milliseconds) {
  json accesses = json::array();
  for (const ResourceAccess& access : pass.accesses) {
    accesses.push_back({{"resource", plan.resources[access.resource].name},
                        {"version", access.version},
                        {"usage", usage_name(access.usage)},
                        {"direction", direction_name(access.direction)},
                        {"range", range_json(access.range)}});
  }
  return {{"order", position},
          {"name", pass.name},
          {"declared_index", pass.declared_index},
          {"queue", queue_name(pass.queue)},
          {"side_effects", pass.side_effects},
          {"depends_on", pass.depends_on},
          {"accesses", std::move(accesses)},
          {"barriers", batch_json(pass.barriers, plan)},
          {"milliseconds", position < milliseconds.size() ? json(milliseconds[position]) : json(nullptr)}};
}

json resource_json(const CompiledResource& resource, const CompiledPlan& plan) {
  json entry{{"name", resource.name},         {"kind", kind_name(resource.kind)},
             {"imported", resource.imported}, {"versions", resource.version_count},
             {"lifetime", nullptr},           {"placement", nullptr}};
  if (resource.kind == ResourceKind::image) {
    entry["format"] = format_name(resource.image.format);
    entry["extent"] = {resource.image.width, resource.image.height};
    entry["layers"] = resource.image.layers;
    entry["mips"] = resource.image.mips;
    entry["usage"] = static_cast<std::uint32_t>(resource.image_usage);
  } else {
    entry["size"] = resource.buffer.size;
    entry["usage"] = static_cast<std::uint32_t>(resource.buffer_usage);
  }
  if (resource.lifetime)
    entry["lifetime"] = {{"first", resource.lifetime->first}, {"last", resource.lifetime->last}};
  if (resource.placement) {
    json reuses = json::array();
    for (std::uint32_t previous : resource.placement->previous_occupants)
      reuses.push_back(plan.resources[previous].name);
    entry["placement"] = {{"heap", resource.placement->heap},
                          {"offset", resource.placement->offset},
                          {"size", resource.placement->size},
                          {"reuses_memory_of", std::move(reuses)}};
  }
  return entry;
}

}  // namespace

std::string to_json(const CompiledPlan& plan, std::span<const double> pass_milliseconds) {
  json passes = json::array();
  for (std::uint32_t position = 0; position < plan.passes.size(); ++position) {
    passes.push_back(pass_json(plan.passes[position], position, plan, pass_milliseconds));
  }
  json culled = json::array();
  for (const CulledPass& pass : plan.culled)
    culled.push_back({{"name", pass.name}, {"declared_index", pass.declared_index}});
  json resources = json::array();
  for (const CompiledResource& resource : plan.resources) resources.push_back(resource_json(resource, plan));
  json heaps = json::array();
  for (const MemoryHeap& heap : plan.heaps) {
    heaps.push_back({{"kind", kind_name(heap.kind)}, {"size", heap.size}, {"alignment", heap.alignment}});
  }
  json exported = json::array();
  for (const ExportedState& state : plan.exported_states) {
    json ranges = json::array();
    for (const RangeState& range : state.states) {
      ranges.push_back({{"range", range_json(range.range)},
                        {"stages", to_string(range.state.stages)},
                        {"access", to_string(range.state.access)},
                        {"layout", to_string(range.state.layout)}});
    }
    exported.push_back({{"resource", plan.resources[state.resource].name}, {"states", std::move(ranges)}});
  }
  const json document{{"passes", std::move(passes)},
                      {"culled", std::move(culled)},
                      {"resources", std::move(resources)},
                      {"heaps", std::move(heaps)},
                      {"memory",
                       {{"unaliased_bytes", plan.memory.unaliased_bytes},
                        {"aliased_bytes", plan.memory.aliased_bytes},
                        {"saved_bytes", plan.memory.saved_bytes()}}},
                      {"final_barriers", batch_json(plan.final_barriers, plan)},
                      {"exported_states", std::move(exported)}};
  return document.dump(2);
}

}  // namespace sg::rg
