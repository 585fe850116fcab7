// SPDX-License-Identifier: MIT
#pragma once
// Carries imported resources' states from one frame to the next, by resource name.
//
// A persistent image (shadow atlas, history buffer) is imported every frame; its initial states
// must be what the previous frame's plan left it in. Ask for them when importing, remember the
// plan after compiling:
//
//   auto atlas = graph.import_image("shadow atlas", desc, states.initial_states("shadow atlas"),
//                                   final_state);
//   ... add passes, compile ...
//   states.remember(*plan);
//
// Unknown names (first frame, or after forget() when the resource was recreated) start
// undefined, which is right for new contents.
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "rendergraph/core/compiled_plan.h"

namespace sg::rg {

class ImportedStates {
 public:
  std::vector<RangeState> initial_states(std::string_view name) const;
  // Stores each of the plan's exported states under its resource's name.
  void remember(const CompiledPlan& plan);
  // The resource was recreated: its contents and layout are gone.
  void forget(std::string_view name);

 private:
  std::unordered_map<std::string, std::vector<RangeState>> states_;
};

}  // namespace sg::rg
