// --init auto's second measurement of the shoulders' height (d_s), once the arms have moved:
// the arms refitted to the silhouettes from each candidate height, the trunk held.
#pragma once

#include <memory>
#include <vector>

#include "tracker/moschini/moschini_tracker.h"

namespace simcap::tracker {

// A frame and the pose the tracker followed it with.
struct TrackedObservation {
  std::shared_ptr<const Observation> obs;
  StickPose pose;
};

struct ShoulderHeight {
  double d_s = 0;
  StickPose last;  // the last frame's pose with its arms refitted from that height
};

// The shoulders' height (d_s, on `evaluations` evenly spaced values in [lo, hi] and the parabola
// through the least: least_on_grid) from which the arms, refitted by the silhouettes alone
// (`options.polish`) with the torso, head and legs held at each frame's tracked pose, explain
// `frames` best. The first frames' search (auto_start.h) scores whole poses, which the trunk's
// capsules follow: the tracker carries the trunk by the error of d_s or leaves the shoulders
// off by it. With the trunk held, only the arms can answer, and arms that have moved away from
// the trunk show where they hang from.
ShoulderHeight shoulders_from_arms(const BodyDimensions& dims, const BodySurface& surface,
                                   const TrackerOptions& options,
                                   const std::vector<TrackedObservation>& frames, double lo,
                                   double hi, int evaluations);

}  // namespace simcap::tracker
