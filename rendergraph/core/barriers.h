// SPDX-License-Identifier: MIT
#pragma once

// Barrier planning: walks the passes in execution order with the state of every subresource
// (per mip, per layer span) and emits, before each pass, the dependencies its uses need, merged
// into one batch; then the transitions of imported resources to their final states.

#include "rendergraph/core/compiled_plan.h"
#include "rendergraph/core/render_graph.h"

namespace sg::rg {

// Fills each pass's `barriers`, `final_barriers` and `exported_states` of `plan`, whose passes,
// resources and placements are already set.
void plan_barriers(const RenderGraph& graph, CompiledPlan& plan);

}  // namespace sg::rg
