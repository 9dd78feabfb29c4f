// simcap's error type: every failure a user can cause is reported as an Error whose message
// names where (file, line, field) and what was expected. The CLI prints it and exits non-zero.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace simcap {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Formats "file:line: field: message" (line <= 0 and an empty field are left out) and throws.
[[noreturn]] void throw_input_error(const std::filesystem::path& file, int line,
                                    std::string_view field, std::string_view message);

}  // namespace simcap
