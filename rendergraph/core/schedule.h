// SPDX-License-Identifier: MIT
#pragma once

// Which passes run, in which order, and what each waits for.
//
// Order: a pass can only name versions that exist when it is declared, so every dependency
// points from an earlier-declared pass to a later one and declaration order is already a
// topological order. Keeping it makes the plan deterministic and lets users reason about it; the
// only cycle the API can express (a pass reading its own output) is rejected at declaration.
//
// Culling: passes with side effects and passes that write imported resources are roots; a pass
// is kept when a kept pass reads a version it produced or overwrites one (a partial write keeps
// the rest of the previous version). Everything else is culled.

#include <cstdint>
#include <vector>

#include "rendergraph/core/render_graph.h"

namespace sg::rg {

struct Schedule {
  std::vector<std::uint32_t> order;   // declaration indices of the passes that run, in order
  std::vector<std::uint32_t> culled;  // declaration indices, ascending
  // Per execution position: the earlier positions it depends on (read-after-write,
  // write-after-write, write-after-read), ascending, without duplicates.
  std::vector<std::vector<std::uint32_t>> depends_on;
};

Schedule schedule_passes(const RenderGraph& graph);

}  // namespace sg::rg
