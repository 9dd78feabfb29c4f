#include "core/html_page.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace simcap {

std::string base64_encode(const std::vector<unsigned char>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    unsigned v = static_cast<unsigned>(bytes[i]) << 16;
    if (n > 1) v |= static_cast<unsigned>(bytes[i + 1]) << 8;
    if (n > 2) v |= bytes[i + 2];
    for (size_t k = 0; k < 4; ++k) {
      out += k <= n ? kAlphabet[(v >> (18 - 6 * k)) & 63] : '=';
    }
  }
  return out;
}

std::string html_row(const std::vector<std::string>& cells, const char* tag) {
  std::string s = "<tr>";
  for (const auto& c : cells) s += std::string("<") + tag + ">" + c + "</" + tag + ">";
  return s + "</tr>\n";
}

std::string html_number(const char* format, double v) {
  if (!std::isfinite(v)) return "&ndash;";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string report_page_start(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         xml_escape(title) +
         "</title>\n<style>\n"
         "body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}\n"
         "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:3px 8px;"
         "text-align:left}\n.grid{display:flex;flex-wrap:wrap;gap:8px}figure{margin:0}"
         "figure img{width:340px}video{max-width:100%}\n</style>\n</head>\n<body>\n<h1>" +
         xml_escape(title) + "</h1>\n";
}

}  // namespace simcap
