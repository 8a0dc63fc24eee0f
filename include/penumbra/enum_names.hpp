#pragma once
// One table of (value, name) per enum, used for parsing, printing and help
// text alike, so names are never duplicated by hand.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace penumbra {

template <class E>
using EnumTable = std::span<const std::pair<E, std::string_view>>;

// Names compare without regard to ASCII case: documents spell techniques
// "PCSS" and "MSM", the tables spell them "pcss" and "msm".
inline bool names_equal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

template <class E>
std::optional<E> parse_enum(EnumTable<E> table, std::string_view name) {
  for (const auto& [value, n] : table) {
    if (names_equal(n, name)) return value;
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
