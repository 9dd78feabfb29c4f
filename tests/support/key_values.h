// Parses the `key=value key=value` summary lines that simcap commands print last, so tests can
// check their fields without std::regex (whose std::function state trips GCC 12's
// -Wmaybe-uninitialized under ASan).
#pragma once

#include <map>
#include <sstream>
#include <string>

namespace simcap::testing {

// The last non-empty line of `text`.
inline std::string last_line(const std::string& text) {
  const size_t end = text.find_last_not_of('\n');
  if (end == std::string::npos) return {};
  const size_t newline = text.rfind('\n', end);
  const size_t start = newline == std::string::npos ? 0 : newline + 1;
  return text.substr(start, end + 1 - start);
}

// The `key=value` tokens of one line; tokens without '=' are ignored.
inline std::map<std::string, std::string> key_values(const std::string& line) {
  std::map<std::string, std::string> fields;
  std::istringstream in(line);
  for (std::string token; in >> token;) {
    const size_t eq = token.find('=');
    if (eq != std::string::npos && eq > 0) fields[token.substr(0, eq)] = token.substr(eq + 1);
  }
  return fields;
}

}  // namespace simcap::testing
