// SPDX-License-Identifier: MIT
#pragma once
// One table of names per enum, declared beside the enum; to_string and parse_enum read it, so the
// command line, the panels, the sidecar, scripts and --stats spell every value the same way:
//
//   enum class Fruit { apple, pear };
//   constexpr EnumNames<Fruit, 2> enum_names(Fruit) { return {{{Fruit::apple, "apple"}, {Fruit::pear,
//   "pear"}}}; }
//
// enum_names takes the enum so that argument-dependent lookup finds the table in the enum's own
// namespace.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace sg {

template <class E, std::size_t N>
using EnumNames = std::array<std::pair<E, std::string_view>, N>;

template <class E>
concept NamedEnum = std::is_enum_v<E> && requires(E value) {
  enum_names(value);
};

template <NamedEnum E>
constexpr std::string_view to_string(E value) {
  for (const auto& [named, name] : enum_names(E{})) {
    if (named == value) return name;
  }
  return "unknown";
}

// The value named `name` (case-sensitive); nullopt for any other text.
template <NamedEnum E>
constexpr std::optional<E> parse_enum(std::string_view name) {
  for (const auto& [value, named] : enum_names(E{})) {
    if (named == name) return value;
  }
  return std::nullopt;
}

// "a, b, c": the names, for messages.
template <NamedEnum E>
std::string enum_name_list() {
  std::string list;
  for (const auto& [value, name] : enum_names(E{})) list.append(list.empty() ? "" : ", ").append(name);
  return list;
}

// Every value, in the table's order.
template <NamedEnum E>
constexpr auto enum_values() {
  constexpr auto names = enum_names(E{});
  std::array<E, names.size()> values{};
  for (std::size_t i = 0; i < names.size(); ++i) values[i] = names[i].first;
  return values;
}

}  // namespace sg
