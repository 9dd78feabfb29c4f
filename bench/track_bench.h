// `simcap bench track`: a tracker's frames/s on a dataset (per stage for Moschini's pipeline),
// against the rate at which the same threads merely decode the images it reads, in the same run.
#pragma once

#include <cstdio>
#include <filesystem>

#include "tracker/track_options.h"

namespace simcap {

struct TrackBenchOptions {
  tracker::TrackOptions track;
  int frames = -1;  // < 0: all
  int repeat = 3;   // runs; the tracker and its baseline alternate
};

// Prints the report; its last line is "frames_per_s=<median over the runs>".
void run_track_benchmark(const std::filesystem::path& dataset, const TrackBenchOptions& options,
                         std::FILE* out);

}  // namespace simcap
