// SPDX-License-Identifier: MIT
#pragma once
// Settings tables (setting.h) on a CLI11 command line: each setting an option checked against its
// type and range, with its help and, as the default --help shows, the value it holds when added.
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "systems/frame/setting.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace sg {

// Registers one setting: `set` receives its checked text; `default_text` is what --help shows.
void add_setting(CLI::App& app, const SettingInfo& info, const std::optional<std::string>& default_text,
                 std::function<void(const std::string&)> set);
// Makes the options of `info.excludes` refuse to be given with `info`'s (all already added).
void add_exclusions(CLI::App& app, const SettingInfo& info);

// Registers every setting of `table` on `app`, writing into `settings`, which must outlive the
// parse.
template <class Settings>
void add_settings(CLI::App& app, std::span<const Setting<Settings>> table, Settings& settings) {
  for (const Setting<Settings>& setting : table) {
    add_setting(app, setting.info, setting.get(settings),
                [&settings, set = setting.set](const std::string& text) { set(settings, text); });
  }
  for (const Setting<Settings>& setting : table) add_exclusions(app, setting.info);
}

// Makes `option` take only what optional_output_problem accepts, for the tools' own outputs, as
// output_file does for a table's.
void check_writable_output(CLI::Option& option);

// Parses argv into what add_settings registered. Returns nullopt to go on, or the exit code to end
// with: 0 after --help, 2 for any usage error (an unknown option, a value out of range, ...).
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv);

}  // namespace sg
