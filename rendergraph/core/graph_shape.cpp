// SPDX-License-Identifier: MIT
#include "rendergraph/core/graph_shape.h"

#include <string_view>

namespace sg::rg {
namespace {

constexpr std::uint64_t fnv_offset = 0xcbf29ce484222325ull;
constexpr std::uint64_t fnv_prime = 0x100000001b3ull;

std::uint64_t fnv1a(std::string_view text) {
  std::uint64_t hash = fnv_offset;
  for (unsigned char c : text) hash = (hash ^ c) * fnv_prime;
  return hash;
}

class ShapeWriter {
 public:
  void add(std::uint64_t word) { shape_.words.push_back(word); }
  void add(const SubresourceRange& range) {
    add(range.base_mip);
    add(range.mip_count);
    add(range.base_layer);
    add(range.layer_count);
  }
  void add(const ResourceState& state) {
    add(static_cast<std::uint64_t>(state.stages));
    add(static_cast<std::uint64_t>(state.access));
    add(static_cast<std::uint64_t>(state.layout));
  }

  GraphShape finish() && {
    shape_.hash = fnv_offset;
    for (std::uint64_t word : shape_.words) shape_.hash = (shape_.hash ^ word) * fnv_prime;
    return std::move(shape_);
  }

 private:
  GraphShape shape_;
};

}  // namespace

GraphShape graph_shape(const RenderGraph& graph) {
  ShapeWriter shape;
  // Counts go before every list so that different splits of the same words cannot collide.
  shape.add(graph.resources().size());
  for (const ResourceDeclaration& resource : graph.resources()) {
    shape.add(fnv1a(resource.name));
    shape.add(static_cast<std::uint64_t>(resource.kind));
    shape.add(resource.imported);
    const ImageDesc& image = resource.image;
    shape.add(image.width);
    shape.add(image.height);
    shape.add(static_cast<std::uint64_t>(image.format));
    shape.add(image.layers);
    shape.add(image.mips);
    shape.add(image.cube_compatible);
    shape.add(resource.buffer.size);
    shape.add(resource.initial_states.size());
    for (const RangeState& initial : resource.initial_states) {
      shape.add(initial.range);
      shape.add(initial.state);
    }
    shape.add(resource.final_state.has_value());
    if (resource.final_state) shape.add(*resource.final_state);
  }
  shape.add(graph.passes().size());
  for (const PassDeclaration& pass : graph.passes()) {
    shape.add(fnv1a(pass.name));
    shape.add(static_cast<std::uint64_t>(pass.queue));
    shape.add(pass.side_effects);
    shape.add(pass.accesses.size());
    for (const ResourceAccess& access : pass.accesses) {
      shape.add(access.resource);
      shape.add(access.version);
      shape.add(static_cast<std::uint64_t>(access.usage));
      shape.add(static_cast<std::uint64_t>(access.direction));
      shape.add(access.range);
      shape.add(access.clear.has_value());  // the load op; the clear value itself is not shape
    }
  }
  return std::move(shape).finish();
}

}  // namespace sg::rg
