// Option checks for numbers with a lower bound. CLI11's PositiveNumber reports a failure as
// "not in range 0.000000 to <DBL_MAX written out>"; these say what was expected.
#pragma once

#include <CLI/CLI.hpp>

namespace simcap::cli {

// A number greater than 0 ("--frames: expected a number greater than 0, got 0").
CLI::Validator positive_number();
// A number of at least 0.
CLI::Validator non_negative_number();

}  // namespace simcap::cli
