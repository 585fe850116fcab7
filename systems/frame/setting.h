// SPDX-License-Identifier: MIT
#pragma once
// A setting declared once: its name, help, type, range and the field it sets. A table of them
// (frame_settings.h's for the engine's frame, the sandbox's for its window and outputs) is the
// only place a setting is spelled: the command line and --help come from it (command_line.h), a
// test checks the README's option list against it, and --stats echoes every setting's value.
//
// Fields are reached through accessors, generic lambdas that serve both the const and the
// mutable settings: [](auto& s) -> auto& { return s.renderer.exposure; }.
#include <charconv>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "systems/frame/output_path.h"
#include "systems/scene/enum_names.h"

namespace sg {

// flag: given or not (no value); choice: one of `choices`; whole: an integer in [min, max];
// number: a real in [min, max]; text: any text the setter accepts.
enum class SettingType { flag, choice, whole, number, text };

// What a setting is, whatever settings struct it writes.
struct SettingInfo {
  std::string_view name;        // --NAME on the command line; NAME in --stats' "settings"
  std::string_view value_name;  // the value's placeholder in the option list ("N", "FILE")
  std::string_view help;
  SettingType type = SettingType::text;
  std::vector<std::string_view> choices;  // choice: the names accepted
  double min = 0.0;                       // whole, number: the range accepted
  double max = 0.0;
  std::vector<std::string_view> excludes;  // settings that cannot be given with this one
};

template <class Settings>
struct Setting {
  SettingInfo info;
  // The value as the command line writes it ("true"/"false" for a flag); nullopt while unset.
  std::function<std::optional<std::string>(const Settings&)> get;
  // Sets the value from text that passed the type's check (a flag: empty text). Throws
  // std::exception with a message for text only the setter can check (a malformed camera).
  std::function<void(Settings&, const std::string&)> set;
};

namespace setting_text {

template <class T>
std::string format(T value) {
  char text[32];
  return {text, std::to_chars(text, text + sizeof(text), value).ptr};
}

template <class T>
T parse(const std::string& text) {
  T value{};
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

// A field's value as text (`write` makes it), or nullopt for an optional field left unset.
template <class T, class Write>
std::optional<std::string> of(const T& value, Write write) {
  return write(value);
}
template <class T, class Write>
std::optional<std::string> of(const std::optional<T>& value, Write write) {
  return value ? std::optional(write(*value)) : std::nullopt;
}

// T, or the T of a std::optional<T>: fields that may be left unset.
template <class T>
struct plain {
  using type = T;
};
template <class T>
struct plain<std::optional<T>> {
  using type = T;
};

}  // namespace setting_text

// --NAME sets a bool field to true.
template <class Settings, class Field>
Setting<Settings> flag(std::string_view name, Field field, std::string_view help) {
  return {{name, {}, help, SettingType::flag},
          [field](const Settings& s) -> std::optional<std::string> { return field(s) ? "true" : "false"; },
          [field](Settings& s, const std::string&) { field(s) = true; }};
}

// --NAME on|off sets a bool field.
template <class Settings, class Field>
Setting<Settings> on_off(std::string_view name, Field field, std::string_view help) {
  return {{name, {}, help, SettingType::choice, {"on", "off"}},
          [field](const Settings& s) -> std::optional<std::string> { return field(s) ? "on" : "off"; },
          [field](Settings& s, const std::string& text) { field(s) = text == "on"; }};
}

// --NAME VALUE sets an enum field (or an optional one) to the value of that name (enum_names.h);
// `accepted`: the values the command line may ask for, when not all.
template <class Settings, class Field>
Setting<Settings> choice(std::string_view name, Field field, std::string_view help,
                         std::vector<std::string_view> accepted = {}) {
  using Value = std::remove_cvref_t<decltype(field(std::declval<Settings&>()))>;
  using Enum = typename setting_text::plain<Value>::type;
  if (accepted.empty()) {
    for (const auto& [value, value_name] : enum_names(Enum{})) accepted.push_back(value_name);
  }
  return {{name, {}, help, SettingType::choice, std::move(accepted)},
          [field](const Settings& s) {
            return setting_text::of(field(s), [](Enum value) { return std::string(to_string(value)); });
          },
          [field](Settings& s, const std::string& text) { field(s) = *parse_enum<Enum>(text); }};
}

// --NAME N sets an unsigned field (or an optional one) to a whole number in [min, max].
template <class Settings, class Field>
Setting<Settings> whole(std::string_view name, std::string_view value_name, Field field, uint64_t min,
                        uint64_t max, std::string_view help) {
  using Value = std::remove_cvref_t<decltype(field(std::declval<Settings&>()))>;
  return {{name, value_name, help, SettingType::whole, {}, double(min), double(max)},
          [field](const Settings& s) {
            return setting_text::of(field(s), [](auto value) { return setting_text::format(value); });
          },
          [field](Settings& s, const std::string& text) {
            field(s) = setting_text::parse<typename setting_text::plain<Value>::type>(text);
          }};
}

// --NAME X sets a float field (or an optional one) to a finite number in [min, max].
template <class Settings, class Field>
Setting<Settings> number(std::string_view name, std::string_view value_name, Field field, double min,
                         double max, std::string_view help) {
  using Value = std::remove_cvref_t<decltype(field(std::declval<Settings&>()))>;
  return {{name, value_name, help, SettingType::number, {}, min, max},
          [field](const Settings& s) {
            return setting_text::of(field(s), [](auto value) { return setting_text::format(value); });
          },
          [field](Settings& s, const std::string& text) {
            field(s) = setting_text::parse<typename setting_text::plain<Value>::type>(text);
          }};
}

// --NAME TEXT sets a string field.
template <class Settings, class Field>
Setting<Settings> text(std::string_view name, std::string_view value_name, Field field,
                       std::string_view help) {
  return {{name, value_name, help, SettingType::text},
          [field](const Settings& s) -> std::optional<std::string> {
            return field(s).empty() ? std::nullopt : std::optional(field(s));
          },
          [field](Settings& s, const std::string& value) { field(s) = value; }};
}

// --NAME PATH sets a string field to a file the run writes (empty: none): a path that cannot be
// written (optional_output_problem) is a usage error.
template <class Settings, class Field>
Setting<Settings> output_file(std::string_view name, std::string_view value_name, Field field,
                              std::string_view help) {
  Setting<Settings> setting = text<Settings>(name, value_name, field, help);
  setting.set = [field](Settings& s, const std::string& path) {
    if (const std::optional<std::string> problem = optional_output_problem(path))
      throw std::runtime_error(*problem);
    field(s) = path;
  };
  return setting;
}

// A table's setting applied to the `Inner` settings that `inner` finds in `Outer` (the frame's
// settings within the sandbox's options).
template <class Outer, class Inner, class Access>
Setting<Outer> within(const Setting<Inner>& setting, Access inner) {
  return {setting.info, [get = setting.get, inner](const Outer& s) { return get(inner(s)); },
          [set = setting.set, inner](Outer& s, const std::string& text) { set(inner(s), text); }};
}

}  // namespace sg
