// SPDX-License-Identifier: MIT
#pragma once

// Reuse of compiled plans across frames whose graphs have the same shape.
//
// The frame loop rebuilds its graph every frame (the setup functions are cheap and capture this
// frame's data) and asks the cache for a plan: computing the shape is one linear walk over the
// declarations, several times cheaper than compile() (figures in rendergraph/README.md). The
// cache keeps the most recently used plans, so a frame that alternates between a few shapes (a
// shadow budget re-rendering different faces each frame) still hits.

#include <cstddef>
#include <memory>
#include <vector>

#include "rendergraph/core/compile.h"
#include "rendergraph/core/graph_shape.h"

namespace sg::rg {

class PlanCache {
 public:
  explicit PlanCache(std::size_t capacity = 8) : capacity_(capacity) {}

  // The plan of an earlier graph shaped like `graph`, or a fresh compile (kept when it succeeds).
  CompileResult get_or_compile(const RenderGraph& graph);

  std::size_t hits() const { return hits_; }
  std::size_t misses() const { return misses_; }
  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    GraphShape shape;
    std::shared_ptr<const CompiledPlan> plan;
  };

  std::size_t capacity_;
  std::vector<Entry> entries_;  // most recently used first
  std::size_t hits_ = 0;
  std::size_t misses_ = 0;
};

}  // namespace sg::rg
