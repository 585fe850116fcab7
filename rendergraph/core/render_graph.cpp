// SPDX-License-Identifier: MIT
#include "rendergraph/core/render_graph.h"

namespace sg::rg {

std::optional<SubresourceRange> resolve(const SubresourceRange& range, const ResourceDeclaration& resource) {
  // 64-bit sums so that huge counts cannot wrap around into a range that looks valid.
  const auto fit = [](std::uint32_t base, std::uint32_t count,
                      std::uint32_t total) -> std::optional<std::uint32_t> {
    if (base >= total) return std::nullopt;
    if (count == remaining) return total - base;
    if (count == 0 || std::uint64_t{base} + count > total) return std::nullopt;
    return count;
  };
  const auto mips = fit(range.base_mip, range.mip_count, resource.mip_count());
  const auto layers = fit(range.base_layer, range.layer_count, resource.layer_count());
  if (!mips || !layers) return std::nullopt;
  return SubresourceRange{range.base_mip, *mips, range.base_layer, *layers};
}

ImageHandle RenderGraph::import_image(std::string name, const ImageDesc& desc,
                                      std::vector<RangeState> initial_states,
                                      std::optional<ResourceState> final_state) {
  const std::uint32_t index = add_resource(std::move(name), ResourceKind::image);
  ResourceDeclaration& resource = resources_[index];
  resource.image = desc;
  resource.imported = true;
  resource.final_state = final_state;
  for (const RangeState& initial : initial_states) {
    if (const auto range = resolve(initial.range, resource)) {
      resource.initial_states.push_back({*range, initial.state});
    } else {
      report(ErrorKind::invalid_range, "import of '" + resource.name + "': initial state for " +
                                           to_string(initial.range) + " lies outside the image (" +
                                           std::to_string(desc.mips) + " mips, " +
                                           std::to_string(desc.layers) + " layers)");
    }
  }
  return {index, 0};
}

ImageHandle RenderGraph::import_image(std::string name, const ImageDesc& desc, ResourceState initial_state,
                                      std::optional<ResourceState> final_state) {
  return import_image(std::move(name), desc, {{SubresourceRange::all(), initial_state}}, final_state);
}

BufferHandle RenderGraph::import_buffer(std::string name, const BufferDesc& desc, ResourceState initial_state,
                                        std::optional<ResourceState> final_state) {
  const std::uint32_t index = add_resource(std::move(name), ResourceKind::buffer);
  ResourceDeclaration& resource = resources_[index];
  resource.buffer = desc;
  resource.imported = true;
  resource.initial_states = {{resource.whole(), initial_state}};
  resource.final_state = final_state;
  return {index, 0};
}

PassBuilder RenderGraph::begin_pass(std::string name, QueueType queue) {
  PassDeclaration& pass = passes_.emplace_back();
  pass.name = std::move(name);
  pass.queue = queue;
  return PassBuilder(*this, static_cast<std::uint32_t>(passes_.size() - 1));
}

std::uint32_t RenderGraph::add_resource(std::string name, ResourceKind kind) {
  ResourceDeclaration& resource = resources_.emplace_back();
  resource.name = std::move(name);
  resource.kind = kind;
  return static_cast<std::uint32_t>(resources_.size() - 1);
}

void RenderGraph::report(ErrorKind kind, std::string message) {
  errors_.push_back({kind, std::move(message)});
}

}  // namespace sg::rg
