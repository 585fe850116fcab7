#pragma once
// Command line of shadowgraph-sandbox.
#include <cstdint>
#include <optional>
#include <string>

#include "rendergraph/vulkan/context.h"

namespace sg::sandbox {

struct Options {
  bool headless = false;
  uint32_t width = 1280;
  uint32_t height = 720;
  std::optional<uint32_t> frames;  // unset: headless renders 3, a window runs until closed
  std::string screenshot;          // PNG of the last frame; headless defaults to shadowgraph.png
  std::string device;              // substring of the Vulkan device name
  bool validation = false;         // also on with SHADOWGRAPH_VALIDATION=1
  bool vsync = true;
};

// Parses argv. On --help or a usage error, prints the message and returns the exit code the
// program should end with.
struct ParseResult {
  std::optional<Options> options;
  int exit_code = 0;
};
ParseResult parse_options(int argc, char** argv);

// The Vulkan context the options ask for (device, validation); presentation off.
vk::ContextOptions context_options(const Options& options);

}  // namespace sg::sandbox
