// `simcap bench ik`: SIK's time per frame on a clip against CCD's and DLS's on the same clip,
// skeleton and limits, measured in the same process (Unzueta's Table 10, last column).
#pragma once

#include <cstdio>
#include <filesystem>

namespace simcap {

struct IkBenchOptions {
  std::filesystem::path motion;  // BVH clip; empty: a 10 s procedural walk on the canonical body
  int repeat = 3;                // runs per method; the median is reported
};

// Prints the table; its last line is "ms_per_frame sik=X ccd=Y dls=Z".
void run_ik_benchmark(const IkBenchOptions& options, std::FILE* out);

}  // namespace simcap
