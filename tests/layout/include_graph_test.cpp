// SPDX-License-Identifier: MIT
// The source tree's include graph has no cycles: between modules (a header and its source file
// count as one) nor between folders, so that every arrow in the architecture runs one way.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace sg::test {
namespace {

namespace fs = std::filesystem;
using Graph = std::map<std::string, std::set<std::string>>;

const fs::path root = SHADOWGRAPH_SOURCE_DIR;
const char* const folders[] = {"ecs", "rendergraph", "systems", "sandbox", "tools", "tests"};

// Module -> the modules it includes (quoted includes of files in the tree; a module is a path
// without its extension).
Graph module_graph() {
  Graph graph;
  const std::regex include(R"(^\s*#include\s+"([^"]+)\")");
  for (const char* folder : folders) {
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root / folder)) {
      const fs::path& path = entry.path();
      if (path.extension() != ".h" && path.extension() != ".cpp") continue;
      const std::string module = fs::relative(path, root).replace_extension().generic_string();
      std::set<std::string>& edges = graph[module];
      std::ifstream in(path);
      for (std::string line; std::getline(in, line);) {
        std::smatch match;
        if (!std::regex_search(line, match, include) || !fs::exists(root / match[1].str())) continue;
        const std::string target = fs::path(match[1].str()).replace_extension().generic_string();
        if (target != module) edges.insert(target);
      }
    }
  }
  return graph;
}

Graph folder_graph(const Graph& modules) {
  Graph graph;
  for (const auto& [module, edges] : modules) {
    const std::string from = fs::path(module).parent_path().generic_string();
    for (const std::string& target : edges) {
      const std::string to = fs::path(target).parent_path().generic_string();
      if (to != from) graph[from].insert(to);
    }
  }
  return graph;
}

// A cycle of `graph` as "a -> b -> a", or empty when there is none.
std::string find_cycle(const Graph& graph) {
  std::map<std::string, int> state;  // 0 unvisited, 1 on the path, 2 done
  std::vector<std::string> path;
  std::string cycle;
  const auto visit = [&](const auto& self, const std::string& node) -> bool {
    state[node] = 1;
    path.push_back(node);
    if (const auto found = graph.find(node); found != graph.end()) {
      for (const std::string& next : found->second) {
        if (state[next] == 1) {
          for (auto it = std::find(path.begin(), path.end(), next); it != path.end(); ++it)
            cycle += *it + " -> ";
          cycle += next;
          return true;
        }
        if (state[next] == 0 && self(self, next)) return true;
      }
    }
    path.pop_back();
    state[node] = 2;
    return false;
  };
  for (const auto& [node, edges] : graph) {
    if (state[node] == 0 && visit(visit, node)) return cycle;
  }
  return {};
}

TEST(IncludeGraph, ModulesIncludeEachOtherOneWayOnly) {
  const Graph modules = module_graph();
  ASSERT_GT(modules.size(), 100u) << "the tree was found at " << root;
  EXPECT_EQ(find_cycle(modules), "");
}

TEST(IncludeGraph, FoldersDependOnEachOtherOneWayOnly) {
  EXPECT_EQ(find_cycle(folder_graph(module_graph())), "");
}

// The layers: the job system knows nothing of the ECS, the ECS and the render graph nothing of
// the systems, the engine (systems/) and the tools nothing of the application (sandbox/), so
// tools render the engine's frame without the sandbox's options.
TEST(IncludeGraph, LowerLayersNeverIncludeHigherOnes) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> never{
      {"ecs/jobs/", {"ecs/", "rendergraph/", "systems/", "sandbox/", "tools/"}},
      {"ecs/", {"rendergraph/", "systems/", "sandbox/", "tools/"}},
      {"rendergraph/", {"systems/", "sandbox/", "tools/"}},
      {"systems/", {"sandbox/", "tools/"}},
      {"tools/", {"sandbox/"}}};
  for (const auto& [module, edges] : module_graph()) {
    for (const auto& [lower, higher] : never) {
      if (!module.starts_with(lower)) continue;
      for (const std::string& target : edges) {
        for (const std::string& folder : higher)
          EXPECT_FALSE(target.starts_with(folder) && !target.starts_with(lower))
              << module << " -> " << target;
      }
    }
  }
}

TEST(IncludeGraph, FindsACycleWhereThereIsOne) {
  const Graph looped{{"a", {"b"}}, {"b", {"c"}}, {"c", {"a"}}};
  EXPECT_EQ(find_cycle(looped), "a -> b -> c -> a");
  EXPECT_EQ(find_cycle(Graph{{"a", {"b"}}, {"b", {}}}), "");
}

}  // namespace
}  // namespace sg::test
