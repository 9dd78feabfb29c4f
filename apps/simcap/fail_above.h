// The --fail-above check of `simcap validate`, `loop` and `demo`: a CI job fails when the MPJPE
// got worse than a limit, with an exit status distinct from errors (1).
#pragma once

#include <optional>

namespace simcap::cli {

inline constexpr int kExitAboveThreshold = 4;

// When `limit_mm` is set and `mpjpe_mm` is above it, says so on stderr (naming `command`) and
// returns kExitAboveThreshold; otherwise returns 0.
int fail_above_status(const char* command, double mpjpe_mm, const std::optional<double>& limit_mm);

}  // namespace simcap::cli
