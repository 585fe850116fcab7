// SPDX-License-Identifier: MIT
#pragma once

// compile(): a declared graph in, an executable plan (or every declaration error) out.

#include <memory>
#include <vector>

#include "rendergraph/core/compiled_plan.h"
#include "rendergraph/core/graph_error.h"
#include "rendergraph/core/render_graph.h"

namespace sg::rg {

struct CompileResult {
  // Shared and immutable so that a cache and the frames in flight can hold the same plan.
  std::shared_ptr<const CompiledPlan> plan;  // null when there are errors
  std::vector<GraphError> errors;

  bool ok() const { return plan != nullptr; }
};

// Schedules and culls passes, derives resource lifetimes and creation usages, packs transients
// into aliased heaps, then plans barriers. Steps live in schedule.h, aliasing.h and barriers.h.
CompileResult compile(const RenderGraph& graph);

}  // namespace sg::rg
