// The names of an option's values, written once beside its enum: the command line turns a
// user's word into a value with them, and summaries and sweep labels print values with them.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

namespace simcap {

template <typename T, std::size_t N>
using NameTable = std::array<std::pair<std::string_view, T>, N>;

template <typename T, std::size_t N>
constexpr std::string_view name_of(const NameTable<T, N>& names, T value) {
  for (const auto& [name, v] : names) {
    if (v == value) return name;
  }
  return "?";  // only for a value the table forgot, which the tables' tests rule out
}

// "a, b or c", for messages that list the choices.
template <typename T, std::size_t N>
std::string choices_text(const NameTable<T, N>& names) {
  std::string s;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) s += i + 1 == N ? " or " : ", ";
    s += names[i].first;
  }
  return s;
}

// on / off switches.
inline constexpr NameTable<bool, 2> kOnOff{{{"on", true}, {"off", false}}};

}  // namespace simcap
