// What a tracker's run over a dataset reports back: how many frames it tracked, how long it
// took, how often it lost the person and started again, and where it wrote the track.
#pragma once

#include <filesystem>
#include <string>

namespace simcap {

struct TrackSummary {
  int frames = 0;
  double seconds = 0;
  int reinitializations = 0;
  // Frames in which the tracker found no person at all (an empty visual hull: the person left
  // the cameras' common view) and held the last pose; the first of them, -1 when none.
  int frames_without_person = 0;
  int first_frame_without_person = -1;
  std::filesystem::path track;
};

// A warning line for a run whose track holds frames without a person (their held pose is not
// a measurement), or "" for one without.
std::string without_person_warning(const TrackSummary& summary);

}  // namespace simcap
