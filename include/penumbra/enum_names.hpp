#pragma once
// One table of (value, name) per enum, used for parsing, printing and help
// text alike, so names are never duplicated by hand.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace penumbra {

template <class E>
using EnumTable = std::span<const std::pair<E, std::string_view>>;

template <class E>
std::optional<E> parse_enum(EnumTable<E> table, std::string_view name) {
  for (const auto& [value, n] : table) {
    if (n == name) return value;
  }
  return std::nullopt;
}

template <class E>
std::string_view enum_name(EnumTable<E> table, E value) {
  for (const auto& [v, n] : table) {
    if (v == value) return n;
  }
  return "?";
}

// "a|b|c"
template <class E>
std::string enum_choices(EnumTable<E> table, std::string_view separator = "|") {
  std::string out;
  for (const auto& [v, n] : table) {
    if (!out.empty()) out += separator;
    out += n;
  }
  return out;
}

}  // namespace penumbra
