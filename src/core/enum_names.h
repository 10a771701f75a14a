// Names of an enum's values as an explicit table in code order: the value a
// file stores for an enum is its index in the table, so the table must list
// the values 0, 1, 2, ... in turn (InCodeOrder, checked at compile time).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace proxsim {

template <typename Enum, std::size_t N>
using EnumNameTable = std::array<std::pair<Enum, const char*>, N>;

/// True when entry i of `table` is the value with code i.
template <typename Enum, std::size_t N>
constexpr bool InCodeOrder(const EnumNameTable<Enum, N>& table) {
  for (std::size_t i = 0; i < N; ++i)
    if (static_cast<std::size_t>(table[i].first) != i) return false;
  return true;
}

/// The name of `value`, or "?" for a value outside the table.
template <typename Enum, std::size_t N>
constexpr const char* NameIn(const EnumNameTable<Enum, N>& table, Enum value) {
  const auto code = static_cast<std::size_t>(value);
  return code < N ? table[code].second : "?";
}

/// Every name, in code order.
template <typename Enum, std::size_t N>
std::vector<std::string> NamesIn(const EnumNameTable<Enum, N>& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.emplace_back(entry.second);
  return names;
}

}  // namespace proxsim
