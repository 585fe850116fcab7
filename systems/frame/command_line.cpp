// SPDX-License-Identifier: MIT
#include "systems/frame/command_line.h"

#include <charconv>
#include <cmath>
#include <exception>
#include <type_traits>
#include <utility>

#include <CLI/CLI.hpp>

#include "systems/frame/output_path.h"

namespace sg {
namespace {

// A whole setting's bounds: doubles hold them exactly up to 2^53, and 2^64 stands for the largest.
uint64_t whole_bound(double bound) { return bound >= 0x1p64 ? UINT64_MAX : static_cast<uint64_t>(bound); }

std::string range_text(const SettingInfo& info) {
  if (info.type == SettingType::whole) {
    return "[" + std::to_string(whole_bound(info.min)) + ", " + std::to_string(whole_bound(info.max)) + "]";
  }
  return "[" + setting_text::format(info.min) + ", " + setting_text::format(info.max) + "]";
}

// The text of a whole or real setting, checked here rather than by CLI11: CLI11 reads unsigned
// integers with strtoull in base 0 ("-3" wraps around to 2^64 - 3, "010" is octal), and
// CLI::Range lets "nan" through (every comparison with NaN is false). A whole number's text is
// rewritten in canonical form, so that CLI11's own conversion agrees.
template <class Number>
CLI::Validator number_in_range(const SettingInfo& info, Number min, Number max, const std::string& kind,
                               const std::string& type_name) {
  const std::string allowed = kind + " in " + range_text(info);
  return CLI::Validator(
      [min, max, allowed](std::string& text) -> std::string {
        Number value{};
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        bool valid = !text.empty() && error == std::errc{} && stop == end && value >= min && value <= max;
        if constexpr (std::is_floating_point_v<Number>) valid = valid && std::isfinite(value);
        if (!valid) return "\"" + text + "\" is not " + allowed;
        if constexpr (std::is_integral_v<Number>) text = std::to_string(value);
        return {};
      },
      type_name + " in " + range_text(info));
}

}  // namespace

void add_setting(CLI::App& app, const SettingInfo& info, const std::optional<std::string>& default_text,
                 std::function<void(const std::string&)> set) {
  const std::string name = "--" + std::string(info.name);
  const std::string help(info.help);
  // A setter's own check (a malformed camera) is a usage error naming the option.
  auto checked = [name, set = std::move(set)](const std::string& text) {
    try {
      set(text);
    } catch (const std::exception& error) {
      throw CLI::ValidationError(name, error.what());
    }
  };
  if (info.type == SettingType::flag) {
    app.add_flag_callback(
        name, [checked] { checked({}); }, help);
    return;
  }
  CLI::Option* option = app.add_option_function<std::string>(name, checked, help);
  if (default_text) option->default_str(*default_text);
  switch (info.type) {
    case SettingType::choice: {
      std::vector<std::string> names(info.choices.begin(), info.choices.end());
      option->check(CLI::IsMember(names));
      break;
    }
    case SettingType::whole:
      option->transform(
          number_in_range(info, whole_bound(info.min), whole_bound(info.max), "a whole number", "UINT"));
      break;
    case SettingType::number:
      option->check(number_in_range(info, info.min, info.max, "a number", "FLOAT"));
      break;
    case SettingType::text:
    case SettingType::flag: option->type_name(std::string(info.value_name)); break;
  }
}

void add_exclusions(CLI::App& app, const SettingInfo& info) {
  CLI::Option* option = app.get_option("--" + std::string(info.name));
  for (const std::string_view other : info.excludes) option->excludes("--" + std::string(other));
}

void check_writable_output(CLI::Option& option) {
  option.check(CLI::Validator(
      [](const std::string& path) { return optional_output_problem(path).value_or(std::string()); }, ""));
}

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 has an exit code per kind of error; Shadowgraph's programs promise 2 for every usage
    // error.
    const bool usage_error = app.exit(e) != static_cast<int>(CLI::ExitCodes::Success);
    return usage_error ? 2 : 0;
  }
  return std::nullopt;
}

}  // namespace sg
