// The tracker's options, declared once for every command that tracks (track, loop, demo, bench
// track) and for the track.* keys of sweep files, so that each reads and acts the same everywhere.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "tracker/track_options.h"

namespace simcap::cli {

enum class TrackOptionScope {
  track,  // everything `simcap track` takes
  loop,   // without --seed (loop's --seed seeds the render), --inspect and --quiet
};

void add_track_options(CLI::App* cmd, tracker::TrackOptions& options, TrackOptionScope scope);

// Refuses, once `cmd` is parsed, an option only other methods read (--effectors: sik's,
// --particles: monocular's, --voxel: moschini's, ...): with a method that does not read it, it
// would be ignored and the run would measure something else than was asked. `cameras`, when
// given, counts the dataset's cameras, which decide what the automatic method becomes (0: unknown).
void refuse_other_methods_options(CLI::App* cmd, const tracker::TrackOptions& options,
                                  std::function<int()> cameras = {});

// Applies a sweep point's track.* keys ("silhouettes" = "bgsub", "voxel_m" = "0.03") through the
// same declarations; an unknown key or a bad value is an Error naming `sweep_file`, the key's line
// there (`lines`, one per key) and the key.
void apply_sweep_track_options(const std::vector<std::pair<std::string, std::string>>& keys,
                               const std::vector<int>& lines,
                               const std::filesystem::path& sweep_file,
                               tracker::TrackOptions& options);

// "moschini, silhouettes gt, init gt": the options a run's summary line shows.
std::string track_options_text(const tracker::TrackOptions& options);

}  // namespace simcap::cli
