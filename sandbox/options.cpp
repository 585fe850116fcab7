// SPDX-License-Identifier: MIT
#include "sandbox/options.h"

#include <sstream>
#include <vector>

#include <CLI/CLI.hpp>

#include "systems/frame/command_line.h"

namespace sg::sandbox {
namespace {

using O = Options;

std::vector<Setting<O>> make_table() {
  std::vector<Setting<O>> table;
  for (const Setting<FrameSettings>& setting : frame_settings_table()) {
    table.push_back(within<O, FrameSettings>(
        setting, [](auto& o) -> auto& { return o.frame; }));
  }
  Setting<O> no_vsync{{"no-vsync", {}, "present without waiting for vertical blank", SettingType::flag},
                      [](const O& o) -> std::optional<std::string> { return o.vsync ? "false" : "true"; },
                      [](O& o, const std::string&) { o.vsync = false; }};
  Setting<O> ui{{"ui",
                 {},
                 "the frame-facts and light-editor panels over the picture (default: on in a window, "
                 "off headless)",
                 SettingType::choice,
                 {"on", "off"}},
                [](const O& o) -> std::optional<std::string> {
                  if (!o.ui) return std::nullopt;
                  return *o.ui ? "on" : "off";
                },
                [](O& o, const std::string& text) { o.ui = text == "on"; }};
  Setting<O> script = text<O>(
      "script", "FILE", [](auto& o) -> auto& { return o.script; },
      "headless, run FILE's commands instead of --frames: select NAME, algorithm NAME, resolution N, update "
      "MODE, priority T, redraw_shadow, move X Y Z, camera EX,EY,EZ,TX,TY,TZ, view lit|shadows, wait N, "
      "screenshot PATH, save, open PATH (another scene, as dropping a glTF on the window does; # "
      "comments; errors name the file and line)");
  script.info.excludes = {"frames"};
  const Setting<O> own[] = {
      flag<O>(
          "headless", [](auto& o) -> auto& { return o.headless; },
          "render offscreen even when a display is available"),
      whole<O>(
          "frames", "N", [](auto& o) -> auto& { return o.frames; }, 1, 1'000'000,
          "render N frames, then exit (headless default: 3)"),
      output_file<O>(
          "screenshot", "PNG", [](auto& o) -> auto& { return o.screenshot; },
          "write the last frame as PNG (headless default: shadowgraph.png)"),
      no_vsync,
      number<O>(
          "max-fps", "N", [](auto& o) -> auto& { return o.max_fps; }, 0.0, 1000.0,
          "in a window, start a frame at most N times a second (0: no cap; also in the Frame panel)"),
      ui,
      script,
      output_file<O>(
          "stats", "JSON", [](auto& o) -> auto& { return o.stats_path; },
          "write facts about the run as JSON (keys listed in sandbox/run_stats.h)"),
      flag<O>(
          "depth-overlay", [](auto& o) -> auto& { return o.depth_overlay; },
          "show the depth buffer in the bottom-right quarter (the render graph's extension example, "
          "sandbox/depth_overlay_pass.cpp)"),
      flag<O>(
          "light-heatmap", [](auto& o) -> auto& { return o.light_heatmap; },
          "color each 16x16 tile by the lights culling listed for it (blue few, red 32 or more, white 256 or "
          "more)"),
      text<O>(
          "dump-shadow-maps", "DIR", [](auto& o) -> auto& { return o.dump_shadow_maps; },
          "after the run, write every light's shadow map as grey PNGs into DIR"),
      output_file<O>(
          "export-gltf", "PATH", [](auto& o) -> auto& { return o.export_gltf; },
          "after the run, write the scene with its edited lights, their shadow settings and the view as "
          "glTF (.gltf, or .glb by the extension), which --scene PATH loads back to the same frame"),
  };
  table.insert(table.end(), std::begin(own), std::end(own));
  return table;
}

Options command_line_options() {
  Options options;
  options.frame = command_line_defaults();
  return options;
}

// "--name VALUE" as the option list shows it.
std::string usage(const SettingInfo& info) {
  std::string text = "--" + std::string(info.name);
  if (info.type == SettingType::choice) {
    text += " ";
    for (size_t i = 0; i < info.choices.size(); ++i) {
      if (i > 0) text += '|';
      text += info.choices[i];
    }
  } else if (info.type != SettingType::flag) {
    text += " " + std::string(info.value_name);
  }
  return text;
}

}  // namespace

std::span<const Setting<Options>> options_table() {
  static const std::vector<Setting<Options>> table = make_table();
  return table;
}

ParseResult parse_options(int argc, char** argv) {
  Options options = command_line_options();
  CLI::App app{"Shadowgraph sandbox: renders a scene in a window, or headless to a PNG."};
  add_settings(app, options_table(), options);
  if (const std::optional<int> exit_code = parse_command_line(app, argc, argv)) {
    return {std::nullopt, *exit_code};
  }
  return {options, 0};
}

std::string option_list() {
  // Usage in a column of 22, help wrapped at 100 columns in a column from 24.
  constexpr size_t help_column = 24;
  constexpr size_t width = 100;
  const Options defaults = command_line_options();
  std::ostringstream out;
  for (const Setting<Options>& setting : options_table()) {
    const SettingInfo& info = setting.info;
    std::string help(info.help);
    const std::optional<std::string> value = setting.get(defaults);
    if (info.type != SettingType::flag && value) help += " (default " + *value + ")";
    std::string line = "  " + usage(info);
    if (line.size() + 2 > help_column) {
      out << line << "\n";
      line.clear();
    }
    std::istringstream words(help);
    for (std::string word; words >> word;) {
      const bool fits = line.size() + 1 + word.size() <= width;
      if (line.size() >= help_column && !fits) {
        out << line << "\n";
        line.clear();
      }
      if (line.size() < help_column)
        line.resize(help_column, ' ');
      else
        line += ' ';
      line += word;
    }
    out << line << "\n";
  }
  return out.str();
}

}  // namespace sg::sandbox
