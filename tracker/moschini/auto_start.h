// Where --init auto starts: the body's proportions and its first pose, from the first frames of
// a person standing upright on the floor, with no ground truth.
#pragma once

#include <vector>

#include "tracker/moschini/body_surface.h"
#include "tracker/moschini/moschini_tracker.h"

namespace simcap::tracker {

struct AutoStart {
  BodyDimensions dims;
  StickPose pose;  // on the first frame
  // How high the ankles of a person of the stature found stand above the floor: the lowest
  // ankle of the first frames tracked should stand there, the legs' length says how far.
  double ankle_height = 0;
};

struct AutoStartOptions {
  int frames = 3;  // the proportions are those that track the first frames at the least cost
  // Searched ranges: the stature the hull's top gives is scaled by up to these factors (its top
  // voxel lies below the head's top; a walking person stoops), and the shoulders' height above
  // the torso's centroid (d_s, in its half-lengths: 0.89 in the neutral humanoid, 1.17 with
  // CMU 131_01's raised clavicles).
  double scale_lo = 0.95, scale_hi = 1.08;
  double shoulders_lo = 0.75, shoulders_hi = 1.35;
  int evaluations = 13;  // per search, evenly spaced over its range
  // The heading: a rig symmetric under a quarter turn (four corner cameras) sees a person
  // standing still at its centre facing one wall much as one facing the next, so the best
  // upright fit is also tried turned by every 360/turns degrees, and the start whose track
  // through the first frames explains the silhouettes best is kept.
  int turns = 4;
};

// The body as --init gt measures it on its first frame, at `pose` on `obs`: the capsules fitted
// to the silhouettes and where the hull's centerline runs off the trunk's and head's sticks.
struct FittedBody {
  BodyDimensions dims;
  BodySurface surface;
};
FittedBody fit_body(const BodyDimensions& dims, const TrackerOptions& options,
                    const StickPose& pose, const Observation& obs);

// `first`: observations of the first frames (at least one with a body in its hull).
// `options`: the tracker's; the search refines at its final refinement's sampling.
AutoStart auto_start(const std::vector<Observation>& first, const TrackerOptions& options,
                     const AutoStartOptions& search = {});

}  // namespace simcap::tracker
