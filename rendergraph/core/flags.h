// SPDX-License-Identifier: MIT
#pragma once

#include <type_traits>

namespace sg::rg {

// Scoped enums that are bitmasks opt in to the operators below with
// `template <> inline constexpr bool is_flag_enum<E> = true;`, so plain enums keep their safety.
template <class E>
inline constexpr bool is_flag_enum = false;

template <class E>
concept FlagEnum = std::is_enum_v<E> && is_flag_enum<E>;

template <FlagEnum E>
constexpr E operator|(E a, E b) {
  using U = std::underlying_type_t<E>;
  return static_cast<E>(static_cast<U>(a) | static_cast<U>(b));
}

template <FlagEnum E>
constexpr E operator&(E a, E b) {
  using U = std::underlying_type_t<E>;
  return static_cast<E>(static_cast<U>(a) & static_cast<U>(b));
}

template <FlagEnum E>
constexpr E operator~(E a) {
  using U = std::underlying_type_t<E>;
  return static_cast<E>(~static_cast<U>(a));
}

template <FlagEnum E>
constexpr E& operator|=(E& a, E b) {
  return a = a | b;
}

template <FlagEnum E>
constexpr E& operator&=(E& a, E b) {
  return a = a & b;
}

template <FlagEnum E>
constexpr bool any(E e) {
  return static_cast<std::underlying_type_t<E>>(e) != 0;
}

template <FlagEnum E>
constexpr bool contains(E set, E subset) {
  return (set & subset) == subset;
}

}  // namespace sg::rg
