#include "tracker/common/track_summary.h"

namespace simcap {

std::string without_person_warning(const TrackSummary& s) {
  if (s.frames_without_person == 0) return {};
  return "warning: no person in " + std::to_string(s.frames_without_person) + " of " +
         std::to_string(s.frames) + " frames (the first: frame " +
         std::to_string(s.first_frame_without_person) +
         "); the track holds the last tracked pose there. Did the person leave the cameras' "
         "common view?\n";
}

}  // namespace simcap
