#include "sandbox/options.h"

#include <CLI/CLI.hpp>

namespace sg::sandbox {

ParseResult parse_options(int argc, char** argv) {
  Options o;
  CLI::App app{"Shadowgraph sandbox: renders a scene in a window, or headless to a PNG."};
  app.add_flag("--headless", o.headless, "Render offscreen even when a display is available");
  app.add_option("--width", o.width, "Output width in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option("--height", o.height, "Output height in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option("--frames", o.frames, "Frames to render, then exit")->check(CLI::Range(1u, 1000000u));
  app.add_option("--screenshot", o.screenshot, "Write the last frame to this PNG file");
  app.add_option("--device", o.device, "Use the Vulkan device whose name contains this text");
  app.add_flag("--validation", o.validation,
               "Enable the Khronos validation layer (also SHADOWGRAPH_VALIDATION=1)");
  app.add_flag("!--no-vsync", o.vsync, "Present without waiting for vertical blank");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return {std::nullopt, app.exit(e)};
  }
  o.validation = o.validation || vk::validation_requested_by_environment();
  return {o, 0};
}

vk::ContextOptions context_options(const Options& options) {
  vk::ContextOptions context;
  context.validation = options.validation;
  context.device_name = options.device;
  return context;
}

}  // namespace sg::sandbox
