// What every fuzz harness shares: simcap's parsers read files, so an input is written to a scratch
// folder (split into several named files where a format spans more than one) before parsing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string_view>

#include "core/error.h"

namespace simcap::fuzz {

// The input as text (the parsers take any bytes).
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// An empty folder of this process's own for one input: the previous input's files are removed.
const std::filesystem::path& fresh_scratch_dir();

// Writes `bytes` to fresh_scratch_dir() / name and returns the path.
std::filesystem::path write_input(std::string_view name, std::string_view bytes);

// Writes an input holding several files: each starts at a line "==> NAME <==" (as `head` prints
// several files) and runs to the next such line. Only the `names` given are written (in
// folders created as needed), so an input cannot reach outside the scratch folder; other
// parts and text before the first header are ignored. Returns the scratch folder.
std::filesystem::path write_parts(std::string_view input,
                                  std::initializer_list<std::string_view> names);

// The API's promise on any input: a value or simcap::Error. Anything else escapes the harness,
// and libFuzzer (or the replay test) reports it as a crash.
template <typename Parse>
void expect_value_or_error(Parse&& parse) {
  try {
    parse();
  } catch (const Error&) {
  }
}

}  // namespace simcap::fuzz
