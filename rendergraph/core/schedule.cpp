// SPDX-License-Identifier: MIT
#include "rendergraph/core/schedule.h"

#include <algorithm>

namespace sg::rg {
namespace {

// The version an access needs to exist: the one it reads, or the one its write overwrites.
std::uint32_t consumed_version(const ResourceAccess& access) {
  return access.direction == Direction::read ? access.version : access.version - 1;
}

std::vector<bool> live_passes(const RenderGraph& graph) {
  const auto passes = graph.passes();
  const auto resources = graph.resources();
  const auto is_root = [&](const PassDeclaration& pass) {
    return pass.side_effects ||
           std::any_of(pass.accesses.begin(), pass.accesses.end(), [&](const ResourceAccess& access) {
             return access.direction == Direction::write && resources[access.resource].imported;
           });
  };
  // Producers are declared before their consumers, so one backward sweep settles liveness.
  std::vector<bool> live(passes.size(), false);
  for (std::size_t p = passes.size(); p-- > 0;) {
    live[p] = live[p] || is_root(passes[p]);
    if (!live[p]) continue;
    for (const ResourceAccess& access : passes[p].accesses) {
      const std::uint32_t producer = resources[access.resource].producers[consumed_version(access)];
      if (producer != invalid_index) live[producer] = true;
    }
  }
  return live;
}

}  // namespace

Schedule schedule_passes(const RenderGraph& graph) {
  const auto passes = graph.passes();
  const auto resources = graph.resources();
  const std::vector<bool> live = live_passes(graph);

  Schedule schedule;
  std::vector<std::uint32_t> position(passes.size(), invalid_index);
  for (std::uint32_t p = 0; p < passes.size(); ++p) {
    if (live[p]) {
      position[p] = static_cast<std::uint32_t>(schedule.order.size());
      schedule.order.push_back(p);
    } else {
      schedule.culled.push_back(p);
    }
  }

  // Readers of each resource's newest version so far, as execution positions.
  std::vector<std::vector<std::uint32_t>> readers(resources.size());
  schedule.depends_on.resize(schedule.order.size());
  for (std::uint32_t position_now = 0; position_now < schedule.order.size(); ++position_now) {
    const PassDeclaration& pass = passes[schedule.order[position_now]];
    std::vector<std::uint32_t>& depends_on = schedule.depends_on[position_now];
    const auto depend_on_producer = [&](const ResourceAccess& access) {
      const std::uint32_t producer = resources[access.resource].producers[consumed_version(access)];
      if (producer != invalid_index && position[producer] != position_now)
        depends_on.push_back(position[producer]);
    };
    // Reads first, so that a pass reading the version its own write replaces counts as a reader
    // of the old version, not the new one.
    for (const ResourceAccess& access : pass.accesses) {
      if (access.direction != Direction::read) continue;
      depend_on_producer(access);
      readers[access.resource].push_back(position_now);
    }
    for (const ResourceAccess& access : pass.accesses) {
      if (access.direction != Direction::write) continue;
      depend_on_producer(access);
      for (std::uint32_t reader : readers[access.resource]) {
        if (reader != position_now) depends_on.push_back(reader);
      }
      readers[access.resource].clear();
    }
    std::sort(depends_on.begin(), depends_on.end());
    depends_on.erase(std::unique(depends_on.begin(), depends_on.end()), depends_on.end());
  }
  return schedule;
}

}  // namespace sg::rg
