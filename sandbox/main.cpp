// SPDX-License-Identifier: MIT
// shadowgraph-sandbox: renders the built-in scene in a window, or headless to a PNG.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>

#include <GLFW/glfw3.h>

#include "sandbox/options.h"
#include "sandbox/run.h"
#include "systems/frame/interrupt.h"
#include "systems/frame/output_path.h"

namespace {

bool display_available() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
}

}  // namespace

int main(int argc, char** argv) {
  // Line by line into a file or a pipe too, so that a long run's log (its progress) shows as it
  // goes, not when the buffer fills or the program ends. A reader that stops early (| grep -q,
  // | head) must not cost the run its files: writing to the closed pipe then fails instead of
  // ending the program. Ctrl-C ends the run after the frame in hand, its files still written.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::signal(SIGPIPE, SIG_IGN);
  sg::catch_interrupts();
  sg::sandbox::ParseResult parsed = sg::sandbox::parse_options(argc, argv);
  if (!parsed.options) return parsed.exit_code;
  sg::sandbox::Options options = *parsed.options;

  try {
    if (!options.script.empty()) options.headless = true;  // scripted runs are offscreen
    if (!options.headless && !display_available()) {
      std::printf("shadowgraph: no display found (DISPLAY and WAYLAND_DISPLAY unset): rendering headless\n");
      options.headless = true;
    }
    if (!options.headless && !glfwInit()) {
      std::printf("shadowgraph: cannot open the display: rendering headless\n");
      options.headless = true;
    }
    if (options.headless && options.screenshot.empty()) {
      options.screenshot = "shadowgraph.png";
      if (const std::optional<std::string> problem = sg::output_path_problem(options.screenshot)) {
        throw std::runtime_error("cannot write the picture: " + *problem +
                                 " (--screenshot PATH chooses another)");
      }
    }
    const int code =
        options.headless ? sg::sandbox::run_headless(options) : sg::sandbox::run_windowed(options);
    if (!options.headless) glfwTerminate();
    return code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowgraph: error: %s\n", e.what());
    return 1;
  }
}
