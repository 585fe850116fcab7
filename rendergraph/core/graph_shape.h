// SPDX-License-Identifier: MIT
#pragma once

// A graph's shape: everything compile() reads from it, flattened into words. Graphs with equal
// shapes compile to equal plans, which is what lets a frame reuse an earlier frame's plan.
// Execute callbacks are not part of the shape (plans name passes by declaration index); names
// enter as 64-bit hashes, so a collision could at worst mislabel a reused plan's dumps.

#include <cstdint>
#include <vector>

#include "rendergraph/core/render_graph.h"

namespace sg::rg {

struct GraphShape {
  std::vector<std::uint64_t> words;
  std::uint64_t hash = 0;

  friend bool operator==(const GraphShape& a, const GraphShape& b) {
    return a.hash == b.hash && a.words == b.words;
  }
};

GraphShape graph_shape(const RenderGraph& graph);

}  // namespace sg::rg
