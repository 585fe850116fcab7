// SPDX-License-Identifier: MIT
#include "rendergraph/core/aliasing.h"

#include <algorithm>
#include <numeric>
#include <optional>

#include "rendergraph/core/span_map.h"

namespace sg::rg {
namespace {

constexpr std::uint64_t image_alignment = 64 * 1024;
constexpr std::uint64_t buffer_alignment = 256;

constexpr std::uint64_t align_up(std::uint64_t value, std::uint64_t alignment) {
  return (value + alignment - 1) & ~(alignment - 1);
}

constexpr bool overlap(const Lifetime& a, const Lifetime& b) {
  return a.first <= b.last && b.first <= a.last;
}

// The lowest offset in `heap` where `request` fits beside the members alive at the same time.
std::optional<std::uint64_t> find_offset(const MemoryHeap& heap, std::span<const std::uint32_t> members,
                                         std::span<const AliasingRequest> requests,
                                         std::span<const MemoryPlacement> placements,
                                         const AliasingRequest& request) {
  std::vector<const MemoryPlacement*> busy;
  for (std::uint32_t member : members) {
    if (overlap(requests[member].lifetime, request.lifetime)) busy.push_back(&placements[member]);
  }
  std::sort(busy.begin(), busy.end(), [](auto* a, auto* b) { return a->offset < b->offset; });
  std::uint64_t offset = 0;
  for (const MemoryPlacement* taken : busy) {
    if (offset + request.size <= taken->offset) break;
    offset = std::max(offset, align_up(taken->offset + taken->size, request.alignment));
  }
  if (offset + request.size > heap.size) return std::nullopt;
  return offset;
}

// Who used each byte last before each member, walking members in the order their lives begin.
void record_previous_occupants(const MemoryHeap& heap, std::vector<std::uint32_t> members,
                               std::span<const AliasingRequest> requests,
                               std::span<MemoryPlacement> placements) {
  std::sort(members.begin(), members.end(), [&](std::uint32_t a, std::uint32_t b) {
    return requests[a].lifetime.first < requests[b].lifetime.first;
  });
  SpanMap<std::uint64_t, std::uint32_t> owner(heap.size, invalid_index);
  for (std::uint32_t member : members) {
    MemoryPlacement& placement = placements[member];
    owner.update(placement.offset, placement.size, [&](std::uint64_t, std::uint64_t, std::uint32_t& who) {
      if (who != invalid_index) placement.previous_occupants.push_back(who);
      who = member;
    });
    auto& previous = placement.previous_occupants;
    std::sort(previous.begin(), previous.end());
    previous.erase(std::unique(previous.begin(), previous.end()), previous.end());
  }
}

}  // namespace

AliasingPlan plan_aliasing(std::span<const AliasingRequest> requests) {
  std::vector<std::uint32_t> by_size(requests.size());
  std::iota(by_size.begin(), by_size.end(), 0u);
  std::stable_sort(by_size.begin(), by_size.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return requests[a].size > requests[b].size; });

  AliasingPlan plan;
  plan.placements.resize(requests.size());
  std::vector<std::vector<std::uint32_t>> members;
  for (std::uint32_t index : by_size) {
    const AliasingRequest& request = requests[index];
    MemoryPlacement& placement = plan.placements[index];
    placement.size = request.size;
    for (std::uint32_t heap = 0; heap < plan.heaps.size() && placement.heap == invalid_index; ++heap) {
      if (plan.heaps[heap].kind != request.kind) continue;
      if (const auto offset =
              find_offset(plan.heaps[heap], members[heap], requests, plan.placements, request)) {
        placement.heap = heap;
        placement.offset = *offset;
      }
    }
    if (placement.heap == invalid_index) {
      placement.heap = static_cast<std::uint32_t>(plan.heaps.size());
      plan.heaps.push_back({request.kind, request.size, 1});
      members.emplace_back();
    }
    MemoryHeap& heap = plan.heaps[placement.heap];
    heap.alignment = std::max(heap.alignment, request.alignment);
    members[placement.heap].push_back(index);
  }
  for (std::uint32_t heap = 0; heap < plan.heaps.size(); ++heap) {
    record_previous_occupants(plan.heaps[heap], members[heap], requests, plan.placements);
  }
  return plan;
}

AliasingRequest estimate_request(const CompiledResource& resource) {
  if (resource.kind == ResourceKind::buffer) {
    return {ResourceKind::buffer, align_up(resource.buffer.size, buffer_alignment), buffer_alignment,
            resource.lifetime.value_or(Lifetime{})};
  }
  const ImageDesc& image = resource.image;
  std::uint64_t bytes = 0;
  for (std::uint32_t mip = 0; mip < image.mips; ++mip) {
    const std::uint64_t width = std::max(1u, image.width >> mip);
    const std::uint64_t height = std::max(1u, image.height >> mip);
    bytes += width * height * bytes_per_texel(image.format);
  }
  return {ResourceKind::image, align_up(bytes * image.layers, image_alignment), image_alignment,
          resource.lifetime.value_or(Lifetime{})};
}

}  // namespace sg::rg
