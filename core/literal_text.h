// Numbers and strings as literal text that other programs parse back exactly (URDF, scene YAML,
// TOML, COLMAP, Python): shortest round-trip decimals and double-quoted strings.
#pragma once

#include <string>
#include <string_view>

namespace simcap {

// Shortest decimal text that parses back to exactly `v`; -0 is written as 0.
std::string shortest_text(double v);
std::string shortest_text(float v);

// shortest_text() with ".0" appended when it would read as an integer (TOML, Python), so that
// typed readers see a float.
std::string float_text(double v);

// `text` in double quotes with backslashes and double quotes escaped (a TOML basic string, a
// Python or JSON string literal for text without control characters).
std::string quoted_text(std::string_view text);

}  // namespace simcap
