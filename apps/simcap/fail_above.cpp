#include "apps/simcap/fail_above.h"

#include <cstdio>

namespace simcap::cli {

int fail_above_status(const char* command, double mpjpe_mm, const std::optional<double>& limit_mm) {
  if (!limit_mm || !(mpjpe_mm > *limit_mm)) return 0;
  std::fprintf(stderr, "simcap %s: FAILED: MPJPE %.1f mm is above --fail-above %.1f mm\n", command,
               mpjpe_mm, *limit_mm);
  return kExitAboveThreshold;
}

}  // namespace simcap::cli
