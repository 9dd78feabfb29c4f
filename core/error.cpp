#include "core/error.h"

namespace simcap {

void throw_input_error(const std::filesystem::path& file, int line, std::string_view field,
                       std::string_view message) {
  std::string text = file.string();
  if (line > 0) text += ":" + std::to_string(line);
  text += ": ";
  if (!field.empty()) {
    text += field;
    text += ": ";
  }
  text += message;
  throw Error(text);
}

}  // namespace simcap
