// SPDX-License-Identifier: MIT
#pragma once

// Human- and tool-readable views of a compiled graph.

#include <span>
#include <string>

#include "rendergraph/core/compiled_plan.h"
#include "rendergraph/core/render_graph.h"

namespace sg::rg {

// Graphviz DOT: passes as boxes (culled ones greyed, executed ones numbered in order), resource
// versions as ellipses, edges labelled with the usage (and the subresources, when not all).
std::string to_dot(const RenderGraph& graph, const CompiledPlan& plan);

// JSON: passes in order with their accesses, dependencies, barriers and milliseconds; culled
// passes; resources with lifetimes, creation usage and memory placement; heaps and bytes saved;
// final barriers and exported states. `pass_milliseconds` (per execution position, from the
// executor's timestamps) fills "milliseconds"; without it they are null.
std::string to_json(const CompiledPlan& plan, std::span<const double> pass_milliseconds = {});

}  // namespace sg::rg
