// SPDX-License-Identifier: MIT
#include "rendergraph/core/imported_states.h"

namespace sg::rg {

std::vector<RangeState> ImportedStates::initial_states(std::string_view name) const {
  const auto found = states_.find(std::string(name));
  return found == states_.end() ? std::vector<RangeState>{} : found->second;
}

void ImportedStates::remember(const CompiledPlan& plan) {
  for (const ExportedState& exported : plan.exported_states) {
    states_[plan.resources[exported.resource].name] = exported.states;
  }
}

void ImportedStates::forget(std::string_view name) { states_.erase(std::string(name)); }

}  // namespace sg::rg
