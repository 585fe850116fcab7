// SPDX-License-Identifier: MIT
#include "rendergraph/core/plan_cache.h"

#include <algorithm>

namespace sg::rg {

CompileResult PlanCache::get_or_compile(const RenderGraph& graph) {
  if (!graph.errors().empty()) return compile(graph);

  GraphShape shape = graph_shape(graph);
  const auto found = std::find_if(entries_.begin(), entries_.end(),
                                  [&](const Entry& entry) { return entry.shape == shape; });
  if (found != entries_.end()) {
    ++hits_;
    std::rotate(entries_.begin(), found, std::next(found));
    return {entries_.front().plan, {}};
  }

  ++misses_;
  CompileResult result = compile(graph);
  if (entries_.size() == capacity_) entries_.pop_back();
  entries_.insert(entries_.begin(), Entry{std::move(shape), result.plan});
  return result;
}

}  // namespace sg::rg
