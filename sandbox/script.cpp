// SPDX-License-Identifier: MIT
#include "sandbox/script.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "systems/frame/output_path.h"

namespace sg::sandbox {
namespace {

[[noreturn]] void fail(const std::string& path, int line, const std::string& problem) {
  throw std::runtime_error(path + ":" + std::to_string(line) + ": " + problem);
}

}  // namespace

std::vector<ScriptStep> parse_script(const std::string& text, const std::string& path) {
  std::vector<ScriptStep> steps;
  std::istringstream lines(text);
  std::string line_text;
  for (int line = 1; std::getline(lines, line_text); ++line) {
    line_text = line_text.substr(0, line_text.find('#'));
    std::istringstream words(line_text);
    std::string command;
    if (!(words >> command)) continue;  // blank or comment
    std::string rest;
    std::getline(words >> std::ws, rest);
    while (!rest.empty() && std::isspace(static_cast<unsigned char>(rest.back()))) rest.pop_back();
    const auto number = [&](const std::string& what, double low, double high) {
      std::istringstream in(rest);
      double value = 0.0;
      std::string extra;
      if (!(in >> value) || (in >> extra) || !std::isfinite(value) || value < low || value > high ||
          value != std::floor(value)) {
        fail(path, line, command + " takes " + what + ", got \"" + rest + "\"");
      }
      return static_cast<uint32_t>(value);
    };
    ScriptStep step;
    step.line = line;
    if (command == "select") {
      if (rest.empty()) fail(path, line, "select takes a light's name");
      step.command = ScriptStep::Select{rest};
    } else if (command == "algorithm") {
      const std::optional<scene::ShadowAlgorithm> algorithm = parse_enum<scene::ShadowAlgorithm>(rest);
      if (!algorithm) fail(path, line, "unknown shadow algorithm \"" + rest + "\"");
      step.command = ScriptStep::Algorithm{*algorithm};
    } else if (command == "resolution") {
      step.command = ScriptStep::Resolution{number("a whole number of texels, 16 to 4096", 16, 4096)};
    } else if (command == "update") {
      const std::optional<scene::ShadowUpdate> update = parse_enum<scene::ShadowUpdate>(rest);
      if (!update) fail(path, line, "update takes auto, every_frame or on_demand, got \"" + rest + "\"");
      step.command = ScriptStep::Update{*update};
    } else if (command == "priority") {
      std::istringstream in(rest);
      float tiers = 0.0f;
      std::string extra;
      if (!(in >> tiers) || (in >> extra) || !(std::abs(tiers) <= scene::max_shadow_priority)) {
        fail(path, line, "priority takes a number of tiers, -4 to 4, got \"" + rest + "\"");
      }
      step.command = ScriptStep::Priority{tiers};
    } else if (command == "redraw_shadow") {
      if (!rest.empty()) fail(path, line, "redraw_shadow takes nothing, got \"" + rest + "\"");
      step.command = ScriptStep::RedrawShadow{};
    } else if (command == "move") {
      std::istringstream in(rest);
      glm::vec3 p;
      std::string extra;
      if (!(in >> p.x >> p.y >> p.z) || (in >> extra) || !std::isfinite(p.x + p.y + p.z)) {
        fail(path, line, "move takes three numbers, got \"" + rest + "\"");
      }
      step.command = ScriptStep::Move{p};
    } else if (command == "camera") {
      try {
        step.command = ScriptStep::Camera{scene::parse_camera(rest)};
      } catch (const std::exception& error) {
        fail(path, line, error.what());
      }
    } else if (command == "wait") {
      step.command = ScriptStep::Wait{number("a whole number of frames, 1 to 100,000", 1, 100'000)};
    } else if (command == "view") {
      if (rest != "lit" && rest != "shadows")
        fail(path, line, "view takes lit or shadows, got \"" + rest + "\"");
      step.command = ScriptStep::View{rest == "shadows" ? LightingView::shadows : LightingView::lit};
    } else if (command == "save") {
      if (!rest.empty()) fail(path, line, "save takes nothing, got \"" + rest + "\"");
      step.command = ScriptStep::Save{};
    } else if (command == "open") {
      if (rest.empty()) fail(path, line, "open takes a .gltf or .glb path or a built-in scene's name");
      step.command = ScriptStep::Open{rest};
    } else if (command == "screenshot") {
      if (rest.empty()) fail(path, line, "screenshot takes a PNG path");
      if (const std::optional<std::string> problem = output_path_problem(rest)) {
        fail(path, line, "screenshot: " + *problem);
      }
      step.command = ScriptStep::Screenshot{rest};
    } else {
      fail(path, line, "unknown command \"" + command + "\"");
    }
    steps.push_back(std::move(step));
  }
  return steps;
}

std::vector<ScriptStep> load_script(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read script " + path);
  std::ostringstream text;
  text << file.rdbuf();
  return parse_script(text.str(), path);
}

}  // namespace sg::sandbox
