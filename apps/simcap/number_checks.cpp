#include "apps/simcap/number_checks.h"

#include <cmath>
#include <cstdlib>
#include <string>

namespace simcap::cli {
namespace {

CLI::Validator bounded_below(bool strict, const char* name) {
  const std::string expected =
      std::string("expected a number ") + (strict ? "greater than 0" : "of at least 0");
  return CLI::Validator(
      [strict, expected](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        const bool number = !text.empty() && end && *end == '\0' && std::isfinite(v);
        if (number && (strict ? v > 0 : v >= 0)) return {};
        return expected + ", got '" + text + "'";
      },
      strict ? "> 0" : ">= 0", name);
}

}  // namespace

CLI::Validator positive_number() {
  return bounded_below(true, "POSITIVE");
}
CLI::Validator non_negative_number() {
  return bounded_below(false, "NONNEGATIVE");
}

}  // namespace simcap::cli
