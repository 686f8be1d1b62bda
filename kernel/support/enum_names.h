#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace mechanist {

/// A table of an enum's values and their spellings in the file format.
template <typename E, std::size_t N>
using EnumNames = std::array<std::pair<E, std::string_view>, N>;

/// The spelling of `value` in `names`, or "?" for a value missing from the table.
template <typename E, std::size_t N>
constexpr std::string_view NameOf(const EnumNames<E, N>& names, E value) {
  for (const auto& [v, name] : names) {
    if (v == value) return name;
  }
  return "?";
}

/// The value spelled `name`, or nothing.
template <typename E, std::size_t N>
constexpr std::optional<E> ValueOf(const EnumNames<E, N>& names, std::string_view name) {
  for (const auto& [v, n] : names) {
    if (n == name) return v;
  }
  return std::nullopt;
}

/// Every spelling in `names`, in the table's order, separated by ", " (for messages).
template <typename E, std::size_t N>
std::string JoinNames(const EnumNames<E, N>& names) {
  std::string joined;
  for (const auto& [v, name] : names) {
    if (!joined.empty()) joined += ", ";
    joined += name;
  }
  return joined;
}

}  // namespace mechanist
