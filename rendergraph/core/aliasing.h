// SPDX-License-Identifier: MIT
#pragma once

// Transient memory planning: transients whose lifetimes do not overlap share memory.
//
// Greedy interval packing: requests are placed largest first; each goes at the lowest offset of
// the first heap of its kind where it overlaps, in memory, no request whose lifetime overlaps its
// own; when none fits, it opens a heap of its own size. Heaps are therefore sized by their first
// (largest) member. The executor may re-run plan_aliasing() with the sizes and alignments the
// device reports instead of the estimates compile() uses.

#include <cstdint>
#include <span>
#include <vector>

#include "rendergraph/core/compiled_plan.h"

namespace sg::rg {

struct AliasingRequest {
  ResourceKind kind = ResourceKind::image;
  std::uint64_t size = 0;
  std::uint64_t alignment = 1;  // a power of two
  Lifetime lifetime;
};

struct AliasingPlan {
  std::vector<MemoryHeap> heaps;
  // Per request; previous_occupants name request indices.
  std::vector<MemoryPlacement> placements;
};

AliasingPlan plan_aliasing(std::span<const AliasingRequest> requests);

// Compile's size estimate for a transient: texel size x extent summed over mips and layers, with
// the 64 KiB alignment desktop GPUs commonly report for optimally tiled images; buffers round to
// 256 bytes. Real requirements come from vkGet*MemoryRequirements in the executor.
AliasingRequest estimate_request(const CompiledResource& resource);

}  // namespace sg::rg
