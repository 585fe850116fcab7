// SPDX-License-Identifier: MIT
#pragma once
// Command line of shadowgraph-sandbox: the frame's settings (systems/frame/frame_settings.h) and
// the sandbox's own, each declared once in a table (setting.h).
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "systems/frame/frame_settings.h"
#include "systems/frame/setting.h"

namespace sg::sandbox {

struct Options {
  FrameSettings frame;  // what the engine renders and how
  bool headless = false;
  std::optional<uint32_t> frames;  // unset: headless renders 3, a window runs until closed
  std::string screenshot;          // PNG of the last frame; headless defaults to shadowgraph.png
  bool vsync = true;
  double max_fps = 0.0;          // --max-fps: the window's frame-rate cap; 0: none
  std::string stats_path;        // --stats: JSON facts about the run; empty: none
  bool depth_overlay = false;    // --depth-overlay: the render-graph extension example
  bool light_heatmap = false;    // --light-heatmap: lights per screen tile
  std::string script;            // --script FILE: commands instead of --frames (script.h); headless only
  std::optional<bool> ui;        // --ui on|off: the panels; unset: on in a window, off headless
  std::string dump_shadow_maps;  // --dump-shadow-maps DIR: each light's map as PNG
  std::string export_gltf;       // --export-gltf PATH: the scene as glTF after the run
};

// Every option, the frame's settings first, in the order --help and the README list them.
std::span<const Setting<Options>> options_table();

// Parses argv. On --help or a usage error, prints the message and returns the exit code the
// program should end with: 0 for --help, 2 for any usage error (unknown option, a value out
// of range, a malformed --camera, ...). Nothing is loaded here: --scene is checked when the
// scene is loaded.
struct ParseResult {
  std::optional<Options> options;
  int exit_code = 0;
};
ParseResult parse_options(int argc, char** argv);

// The README's option list as the table declares it: each option with its value, help and
// default, wrapped as the README shows it (a test keeps the README equal to it).
std::string option_list();

}  // namespace sg::sandbox
