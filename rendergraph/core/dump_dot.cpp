// SPDX-License-Identifier: MIT
#include <ostream>
#include <set>
#include <sstream>
#include <utility>

#include "rendergraph/core/dump.h"

namespace sg::rg {
namespace {

std::string escaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

// Streams pieces instead of concatenating strings: shorter, and GCC 12 misreports (-Wrestrict)
// some chains of std::string operator+.
void write_version_node(std::ostream& out, const ResourceAccess& access) {
  out << 'r' << access.resource << 'v' << access.version;
}

void write_edge(std::ostream& out, std::uint32_t pass, const ResourceAccess& access,
                const ResourceDeclaration& resource) {
  out << "  ";
  if (access.direction == Direction::read) {
    write_version_node(out, access);
    out << " -> p" << pass;
  } else {
    out << 'p' << pass << " -> ";
    write_version_node(out, access);
  }
  out << " [label=\"" << usage_name(access.usage);
  if (access.range != resource.whole()) out << "\\n" << to_string(access.range);
  out << "\"];\n";
}

}  // namespace

std::string to_dot(const RenderGraph& graph, const CompiledPlan& plan) {
  const auto passes = graph.passes();
  const auto resources = graph.resources();
  std::vector<std::uint32_t> position(passes.size(), invalid_index);
  for (std::uint32_t p = 0; p < plan.passes.size(); ++p) position[plan.passes[p].declared_index] = p;

  std::ostringstream dot;
  dot << "digraph render_graph {\n  rankdir=LR;\n"
      << "  node [fontname=\"Helvetica\", fontsize=10];\n  edge [fontname=\"Helvetica\", fontsize=9];\n";
  std::set<std::pair<std::uint32_t, std::uint32_t>> drawn_versions;
  for (std::uint32_t p = 0; p < passes.size(); ++p) {
    const PassDeclaration& pass = passes[p];
    dot << "  p" << p << " [shape=box, ";
    if (position[p] == invalid_index) {
      dot << "style=filled, fillcolor=\"#dddddd\", fontcolor=\"#888888\", label=\"" << escaped(pass.name)
          << "\\nculled\"];\n";
    } else {
      dot << "label=\"#" << position[p] << " " << escaped(pass.name) << "\\n"
          << queue_name(pass.queue) << "\"];\n";
    }
    const auto draw_version = [&](const ResourceAccess& access) {
      const ResourceDeclaration& resource = resources[access.resource];
      if (!drawn_versions.emplace(access.resource, access.version).second) return;
      dot << "  ";
      write_version_node(dot, access);
      dot << " [shape=ellipse, label=\"" << escaped(resource.name) << " v" << access.version
          << (resource.imported ? "\\nimported" : "") << "\"];\n";
    };
    for (const ResourceAccess& access : pass.accesses) {
      draw_version(access);
      write_edge(dot, p, access, resources[access.resource]);
      // A write without a clear keeps the earlier contents outside (or under) what it draws:
      // it depends on the version it replaces, shown dashed.
      if (access.direction == Direction::write && !access.clear &&
          has_earlier_contents(access, resources[access.resource].imported)) {
        ResourceAccess consumed = access;
        consumed.version = access.version - 1;
        draw_version(consumed);
        dot << "  ";
        write_version_node(dot, consumed);
        dot << " -> p" << p << " [style=dashed, label=\"previous contents\"];\n";
      }
    }
  }
  dot << "}\n";
  return dot.str();
}

}  // namespace sg::rg
