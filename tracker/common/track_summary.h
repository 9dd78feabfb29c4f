// What a tracker's run over a dataset reports back: how many frames it tracked, how long it
// took, how often it lost the person and started again, and where it wrote the track.
#pragma once

#include <filesystem>

namespace simcap {

struct TrackSummary {
  int frames = 0;
  double seconds = 0;
  int reinitializations = 0;
  std::filesystem::path track;
};

}  // namespace simcap
