#include "core/literal_text.h"

#include <charconv>

namespace simcap {
namespace {

template <class T>
std::string shortest(T v) {
  if (v == 0) v = 0;  // "-0" reads back equal but puzzles people
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, ptr);
}

}  // namespace

std::string shortest_text(double v) {
  return shortest(v);
}
std::string shortest_text(float v) {
  return shortest(v);
}

std::string float_text(double v) {
  std::string text = shortest(v);
  if (text.find_first_of(".en") == std::string::npos) text += ".0";
  return text;
}

std::string quoted_text(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace simcap
